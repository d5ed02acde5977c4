// The fits started over HTTP (POST /v1/fits; docs/fits.md "Over HTTP") run in the background on
// a bounded WorkerPool (api/work/worker_pool.h: never the HTTP query threads, a full queue
// refuses with 503 busy, each worker with its own database connection). Each fit is a row of
// the fits table, recorded `queued` before it is queued (record_queued_fit), so that it outlives
// the process: run_fit then writes its progress and stage as it runs, and its outcome. When the
// pool stops, a running fit is cancelled (recorded `interrupted`) and queued ones are recorded
// `interrupted`; what a killed process left queued or running becomes `interrupted` at the next
// start (interrupt_unfinished_fits).
// Thread-safety: every member may be called from any thread.
#pragma once

#include <atomic>
#include <cstdint>

#include "api/fits/fit_runner.h"
#include "api/work/worker_pool.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

struct FitPoolOptions {
  unsigned workers = 1;
  std::size_t max_queued = 8;
  // Threads each fit uses for its captures (EvaluationOptions::capture_threads).
  unsigned capture_threads = 1;
};

class FitPool {
 public:
  using OpenDatabase = WorkerPool::OpenDatabase;

  FitPool(OpenDatabase open_database, const FitPoolOptions& options = {});
  // Cancels the running fits, drops the queued ones, joins the workers.
  ~FitPool();
  FitPool(const FitPool&) = delete;
  FitPool& operator=(const FitPool&) = delete;

  // Records the fit (queued) and queues it; returns its id. The request must have been checked
  // (parse_fit_request). Throws ApiError 503 (busy) when the queue is full, before anything is
  // recorded.
  std::int64_t submit(FitRequest request);
  // Blocks until nothing is queued or running.
  void wait_idle();

 private:
  OpenDatabase open_database_;
  FitPoolOptions options_;
  std::atomic<bool> cancel_{false};
  WorkerPool workers_;  // last: stopped and joined before the rest goes
};

// At start-up, before a pool runs: fits a stopped process left queued or running become
// `interrupted`; returns how many.
int interrupt_unfinished_fits(storage::Database& db);

}  // namespace clearsky::api
