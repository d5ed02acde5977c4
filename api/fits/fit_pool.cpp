// Background fits with their stored rows (fit_pool.h).
#include "api/fits/fit_pool.h"

#include <memory>

#include "storage/repositories/fit_repository.h"

namespace clearsky::api {
namespace {

constexpr const char* kStoppedBeforeRun = "interrupted: the server stopped before this fit ran";
constexpr const char* kStoppedDuringRun = "interrupted: the server stopped during the fit";

}  // namespace

FitPool::FitPool(OpenDatabase open_database, const FitPoolOptions& options)
    : open_database_(open_database),
      options_(options),
      workers_(std::move(open_database), {options.workers, options.max_queued, "fits", 30}) {}

FitPool::~FitPool() {
  cancel_ = true;
  workers_.stop();
}

std::int64_t FitPool::submit(FitRequest request) {
  WorkerPool::Reservation place = workers_.reserve();
  request.capture_threads = options_.capture_threads;
  request.cancel = &cancel_;
  request.progress = nullptr;
  std::int64_t id = 0;
  {
    storage::Database db = open_database_();
    id = record_queued_fit(db, request);
  }
  auto shared_request = std::make_shared<const FitRequest>(std::move(request));
  WorkerTask task;
  // run_fit records the failure (or the cancellation) itself before it rethrows; failed covers
  // what happens before it starts (the worker's connection cannot be opened).
  task.run = [id, shared_request](storage::Database& db) { run_fit(db, *shared_request, id); };
  task.failed = [this, id](const std::string& error) {
    storage::Database db = open_database_();
    storage::FitRepository(db).fail(id, cancel_ ? kStoppedDuringRun : error,
                                    cancel_ ? "interrupted" : "failed");
  };
  task.dropped = [this, id] {
    storage::Database db = open_database_();
    storage::FitRepository(db).fail(id, kStoppedBeforeRun, "interrupted");
  };
  workers_.submit(std::move(place), std::move(task));
  return id;
}

void FitPool::wait_idle() { workers_.wait_idle(); }

int interrupt_unfinished_fits(storage::Database& db) {
  return storage::FitRepository(db).interrupt_unfinished(kStoppedDuringRun);
}

}  // namespace clearsky::api
