// Background dataset imports (import_pool.h).
#include "api/imports/import_pool.h"

#include "api/datasets/datasets_api.h"
#include "api/error/api_error.h"

namespace clearsky::api {

ImportPool::ImportPool(OpenDatabase open_database, const ImportPoolOptions& options)
    : open_database_(open_database),
      options_(options),
      workers_(std::move(open_database), {options.workers, options.max_queued, "imports", 30}) {}

ImportPool::~ImportPool() { workers_.stop(); }

std::int64_t ImportPool::submit(storage::Database& db, const storage::NewImport& what,
                                const std::filesystem::path& source,
                                std::unique_ptr<UploadSpool> spool,
                                const std::filesystem::path& confine_to,
                                const storage::KiderImportOptions& site_clock) {
  WorkerPool::Reservation place = workers_.reserve();
  // The row is written holding a place but not the pool's lock: the database may wait for an
  // import's commit.
  const std::int64_t id = storage::ImportRepository(db).create(what);
  auto task =
      std::make_shared<Task>(Task{id, what, source, std::move(spool), confine_to, site_clock});
  WorkerTask work;
  work.started = [this, task] {
    std::lock_guard lock(mutex_);
    running_[task->id] = storage::ImportProgress{};
  };
  work.run = [this, task](storage::Database& worker_db) {
    run(worker_db, *task);
    end(*task);
  };
  // Recording the outcome failed (the database is unavailable): start-up marks the row failed
  // if it is left unfinished.
  work.failed = [this, task](const std::string& error) {
    end(*task);
    if (options_.log) options_.log(task->id, false, "cannot record the outcome: " + error);
  };
  work.dropped = [this, task] {
    task->spool.reset();
    try {
      storage::Database cancel_db = open_database_();
      storage::ImportRepository(cancel_db).fail(
          task->id, {}, "cancelled", "cancelled: the server stopped before the import ran");
    } catch (const std::exception& e) {
      // Start-up marks it failed all the same (fail_unfinished).
      if (options_.log)
        options_.log(task->id, false, std::string("cannot record the cancellation: ") + e.what());
    }
  };
  workers_.submit(std::move(place), std::move(work));
  return id;
}

std::optional<storage::ImportProgress> ImportPool::live_progress(std::int64_t id) const {
  std::lock_guard lock(mutex_);
  const auto found = running_.find(id);
  if (found == running_.end()) return std::nullopt;
  return found->second;
}

void ImportPool::wait_idle() { workers_.wait_idle(); }

void ImportPool::end(Task& task) {
  task.spool.reset();
  std::lock_guard lock(mutex_);
  running_.erase(task.id);
}

void ImportPool::run(storage::Database& db, Task& task) {
  storage::ImportRepository imports(db);
  imports.start(task.id);
  const auto record = [this, id = task.id](const storage::ImportProgress& p) {
    std::lock_guard lock(mutex_);
    running_[id] = p;
  };
  const auto last = [this, id = task.id] {
    std::lock_guard lock(mutex_);
    return running_[id];
  };
  std::string error_code;
  std::string error;
  nlohmann::ordered_json report;
  try {
    report = import_dataset(
        db, task.what.dataset, task.what.format,
        {task.source, task.confine_to, options_.limits,
         task.what.source == "path" ? task.what.path : std::string("upload"), task.site_clock},
        record);
  } catch (const ApiError& e) {
    error_code = e.code();
    error = e.what();
  } catch (const std::exception& e) {
    error_code = "internal_error";
    error = e.what();
  }
  // The upload is no longer needed whatever happened; removed before the outcome is recorded.
  task.spool.reset();
  if (error_code.empty()) {
    imports.succeed(task.id, last(), report.dump());
    if (options_.log)
      options_.log(task.id, true,
                   "into '" + task.what.dataset + "': " + std::to_string(report["added"].size()) +
                       " captures added, " + std::to_string(report["unchanged"].size()) +
                       " unchanged");
  } else {
    imports.fail(task.id, last(), error_code, error);
    if (options_.log) options_.log(task.id, false, "into '" + task.what.dataset + "': " + error);
  }
}

}  // namespace clearsky::api
