// cpp-httplib's worker pool, elastic and bounded: a connection task goes to an idle worker, or
// to a new thread while there are fewer than max_workers; beyond that at most max_queued
// accepted connections wait, and enqueue() (called by the accepting thread) then blocks, so
// further connections stay in the kernel's listen backlog. Workers idle for idle_exit end,
// down to min_workers. cpp-httplib runs a connection on one worker for its whole life, so a
// worker is a connection slot: growing on demand lets held connections (slow or idle clients)
// take threads without taking the last one (docs/deployment.md "Limits in the server").
// The pool publishes busy workers and queued connections in a WorkerLoad. Thread-safe.
#pragma once

#include <httplib.h>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>

#include "server/http/worker_load.h"

namespace clearsky::server {

class ElasticTaskQueue final : public httplib::TaskQueue {
 public:
  struct Options {
    unsigned max_workers = 512;
    unsigned min_workers = 4;
    std::size_t max_queued = 256;
    std::chrono::milliseconds idle_exit{10000};
  };
  // load must outlive the queue.
  ElasticTaskQueue(const Options& options, WorkerLoad& load);
  ~ElasticTaskQueue() override;
  void enqueue(std::function<void()> task) override;
  // Runs the queued tasks, then waits for every worker to end.
  void shutdown() override;

  unsigned workers() const;

 private:
  void start_worker();  // with mutex_ held
  void work();
  void publish();  // with mutex_ held

  Options options_;
  WorkerLoad& load_;
  mutable std::mutex mutex_;
  std::condition_variable not_empty_, not_full_, all_ended_;
  std::deque<std::function<void()>> tasks_;
  unsigned workers_ = 0, idle_ = 0, busy_ = 0;
  bool shutting_down_ = false;
};

}  // namespace clearsky::server
