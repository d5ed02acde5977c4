// The scheduler of evaluation jobs (/v1/jobs): once a minute it reads the jobs table and
// hands each due job (next_run at or before now, not paused) to the evaluation pool. Its
// state is the jobs table, so it survives restarts:
// - a due run is claimed in the database (compare-and-set of next_run) before it is queued,
//   and the next run is computed from NOW, so after downtime a job catches up at most once;
// - a job whose previous run is still queued or running is not started again (that
//   occurrence is skipped and logged), so the same job never runs twice concurrently;
// - a job without a next run (created by an older program) gets one, without running;
// - a job that re-fits its dataset (api/jobs/job_refit.h) first runs its fit on the
//   scheduler's own fit worker (api/work/worker_pool.h, one worker, apart from the HTTP threads
//   and the evaluation workers; run_fit as POST /v1/fits runs it), records it as the job's
//   last fit, and only when it succeeded hands the evaluation with `"fit"` = its id to the
//   pool: a failed fit fails the occurrence (the fit reads failed with its error, no
//   evaluation runs with older values). The job is in flight from the fit to the evaluation's
//   end. Stopping the scheduler cancels a running fit (recorded interrupted).
// tick() is the whole logic and takes the time, for tests; start() runs it on a thread.
// Thread-safety: tick() from one thread at a time; start()/stop() from the owner.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>

#include "api/evaluation/evaluation_pool.h"
#include "api/fits/fit_runner.h"
#include "api/work/worker_pool.h"
#include "storage/repositories/job_repository.h"
#include "storage/sqlite/database.h"

namespace clearsky::server {

struct TickReport {
  int started = 0;          // jobs handed to the pool (or to the fit worker, to re-fit first)
  int skipped_running = 0;  // due but still running from before
  int failed_to_start = 0;  // due but their evaluation could not be built or queued
};

class Scheduler {
 public:
  Scheduler(api::EvaluationPool::OpenDatabase open_database, api::EvaluationPool& pool,
            std::string software_version);
  ~Scheduler();
  Scheduler(const Scheduler&) = delete;
  Scheduler& operator=(const Scheduler&) = delete;

  TickReport tick(std::int64_t now_unix_s);
  // Ticks now and then at the start of every minute until stop().
  void start();
  void stop();
  // Jobs whose fit or evaluation is queued or running.
  std::set<std::int64_t> in_flight() const;
  // Blocks until no fit is queued or running (their evaluations are then in the pool).
  void wait_for_fits();

 private:
  // Queues the job's evaluation; the job leaves in_flight when it ends.
  void submit_evaluation(api::EvaluationRequest request, const storage::JobRecord& job);
  // The work of the fit worker for one occurrence of a re-fitting job.
  void refit_then_evaluate(storage::Database& db, const storage::JobRecord& job,
                           const api::FitRequest& fit);
  void leave_in_flight(std::int64_t job_id);

  api::EvaluationPool::OpenDatabase open_database_;
  api::EvaluationPool& pool_;
  std::string software_version_;
  std::optional<storage::Database> db_;
  // Shared with the pool's completion callbacks, which may outlive the scheduler.
  struct InFlight {
    std::mutex mutex;
    std::set<std::int64_t> jobs;
  };
  std::shared_ptr<InFlight> in_flight_ = std::make_shared<InFlight>();
  std::mutex mutex_;
  std::condition_variable stop_signal_;
  bool stopping_ = false;
  std::thread thread_;
  std::atomic<bool> cancel_fits_{false};
  api::WorkerPool fits_;  // last: stopped and joined before the rest goes
};

}  // namespace clearsky::server
