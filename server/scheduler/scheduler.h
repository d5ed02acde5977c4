// The scheduler of evaluation jobs (/v1/jobs): once a minute it reads the jobs table and
// hands each due job (next_run at or before now, not paused) to the evaluation pool. Its
// state is the jobs table, so it survives restarts:
// - a due run is claimed in the database (compare-and-set of next_run) before it is queued,
//   and the next run is computed from NOW, so after downtime a job catches up at most once;
// - a job whose previous run is still queued or running is not started again (that
//   occurrence is skipped and logged), so the same job never runs twice concurrently;
// - a job without a next run (created by an older program) gets one, without running.
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
#include "storage/sqlite/database.h"

namespace clearsky::server {

struct TickReport {
  int started = 0;          // jobs handed to the pool
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
  // Jobs whose evaluation is queued or running.
  std::set<std::int64_t> in_flight() const;

 private:
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
};

}  // namespace clearsky::server
