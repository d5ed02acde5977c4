// The bounded pool of background workers that runs evaluations (api/evaluation/
// evaluation_pool.h) and dataset imports (api/imports/import_pool.h), apart from the HTTP query
// threads so that long work never starves queries: a fixed number of worker threads, a bounded
// queue (a full queue refuses with 503 busy and Retry-After), and each worker with its own
// database connection (storage/sqlite/database.h: one connection per thread), opened when its
// first task runs. A task that throws is a failure: the worker's connection is closed (the
// next task opens a fresh one, so that a broken connection or a transaction left open never
// outlives the task) and the task's `failed` hook is told why.
// A submission may first reserve its place (reserve()) and do work that must not hold the
// pool's lock (e.g. write its row) before it is queued; an unused reservation is released.
// stop() lets running tasks end, drops the queued ones (their `dropped` hook is called after
// the workers are joined) and joins; the destructor stops.
// Thread-safety: every member may be called from any thread, stop() from one at a time.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "storage/sqlite/database.h"

namespace clearsky::api {

struct WorkerPoolOptions {
  unsigned workers = 1;
  std::size_t max_queued = 16;
  std::string task_noun = "tasks";  // in the 503's message: "16 tasks are queued"
  int retry_after_s = 30;
};

struct WorkerTask {
  // The task left the queue for a worker (before the worker's connection is opened).
  std::function<void()> started;
  // Runs on a worker with the worker's connection.
  std::function<void(storage::Database&)> run;
  // The task threw (or the connection could not be opened): why. Called on the worker, after
  // the connection was closed.
  std::function<void(const std::string& error)> failed;
  // The pool stopped before the task ran.
  std::function<void()> dropped;
};

class WorkerPool {
 public:
  using OpenDatabase = std::function<storage::Database()>;

  // A place in the queue, held until the task is submitted or the reservation destroyed.
  class Reservation {
   public:
    Reservation(Reservation&& other) noexcept : pool_(other.pool_) { other.pool_ = nullptr; }
    Reservation& operator=(Reservation&&) = delete;
    Reservation(const Reservation&) = delete;
    Reservation& operator=(const Reservation&) = delete;
    ~Reservation();

   private:
    friend class WorkerPool;
    explicit Reservation(WorkerPool* pool) : pool_(pool) {}
    WorkerPool* pool_;
  };

  WorkerPool(OpenDatabase open_database, WorkerPoolOptions options);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // Throws ApiError 503 (busy, with Retry-After) when queued and reserved tasks fill the queue.
  Reservation reserve();
  // Queues the task in the reserved place; returns its sequence number (1, 2, ... per pool).
  std::int64_t submit(Reservation reservation, WorkerTask task);
  std::int64_t submit(WorkerTask task) { return submit(reserve(), std::move(task)); }
  // Blocks until nothing is reserved, queued or running.
  void wait_idle();
  void stop();

 private:
  struct Queued {
    std::int64_t id = 0;
    WorkerTask task;
  };
  void release();
  void work();

  OpenDatabase open_database_;
  WorkerPoolOptions options_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable idle_;
  std::deque<Queued> queue_;
  std::size_t reserved_ = 0;
  unsigned running_ = 0;
  std::int64_t next_id_ = 1;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace clearsky::api
