// Worker threads started on demand over a bounded FIFO of connection tasks.
#include "server/http/elastic_task_queue.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <thread>

#include "server/memory/heap_bounds.h"

namespace clearsky::server {

ElasticTaskQueue::ElasticTaskQueue(const Options& options, WorkerLoad& load)
    : options_(options), load_(load) {
  options_.max_workers = std::max(1u, options_.max_workers);
  options_.min_workers = std::min(options_.min_workers, options_.max_workers);
  options_.max_queued = std::max<std::size_t>(1, options_.max_queued);
  std::lock_guard lock(mutex_);
  for (unsigned i = 0; i < options_.min_workers; ++i) start_worker();
}

ElasticTaskQueue::~ElasticTaskQueue() { shutdown(); }

unsigned ElasticTaskQueue::workers() const {
  std::lock_guard lock(mutex_);
  return workers_;
}

void ElasticTaskQueue::start_worker() {
  // Detached: a worker that ends on its own (idle) cannot be joined by anyone; shutdown()
  // waits for the count of workers to reach zero instead.
  std::thread([this] { work(); }).detach();
  ++workers_;
  ++idle_;
}

void ElasticTaskQueue::publish() {
  // Queued tasks that an idle worker is about to take do not wait for one.
  load_.set(busy_, tasks_.size() > idle_ ? tasks_.size() - idle_ : 0);
}

void ElasticTaskQueue::enqueue(std::function<void()> task) {
  std::unique_lock lock(mutex_);
  not_full_.wait(lock, [&] {
    return shutting_down_ || tasks_.size() < options_.max_queued || workers_ < options_.max_workers;
  });
  if (shutting_down_) {
    // Run it here rather than drop it: the task owns (and closes) its connection's socket.
    lock.unlock();
    try {
      task();
    } catch (...) {
      spdlog::error("http: a connection task failed during shutdown");
    }
    return;
  }
  tasks_.push_back(std::move(task));
  // Every waiting task needs its own worker: an idle one, else a new one below the cap.
  if (idle_ < tasks_.size() && workers_ < options_.max_workers) start_worker();
  publish();
  not_empty_.notify_one();
}

void ElasticTaskQueue::shutdown() {
  std::unique_lock lock(mutex_);
  shutting_down_ = true;
  not_empty_.notify_all();
  not_full_.notify_all();
  all_ended_.wait(lock, [&] { return workers_ == 0; });
}

void ElasticTaskQueue::work() {
  std::unique_lock lock(mutex_);
  while (true) {
    // idle_ counts this worker from its start (start_worker) or from the end of its last task.
    const bool woken = not_empty_.wait_for(lock, options_.idle_exit,
                                           [&] { return shutting_down_ || !tasks_.empty(); });
    if (tasks_.empty()) {
      if (shutting_down_ || (!woken && workers_ > options_.min_workers)) break;
      continue;
    }
    std::function<void()> task = std::move(tasks_.front());
    tasks_.pop_front();
    --idle_;
    ++busy_;
    publish();
    not_full_.notify_one();
    lock.unlock();
    try {
      task();
    } catch (const std::exception& e) {
      spdlog::error("http worker: {}", e.what());
    } catch (...) {
      spdlog::error("http worker: unknown exception");
    }
    task = nullptr;  // the connection's state goes before the worker counts as idle again
    lock.lock();
    --busy_;
    ++idle_;
    publish();
  }
  --idle_;
  --workers_;
  publish();
  not_full_.notify_one();
  const bool retired = !shutting_down_;
  // Nothing of this object is touched after the lock is released: shutdown() may then return
  // and the queue be destroyed.
  if (workers_ == 0) all_ended_.notify_all();
  lock.unlock();
  // The load fell: what the finished connections freed goes back to the system instead of
  // staying in malloc's arenas (server/memory/heap_bounds.h).
  if (retired) release_free_heap_memory();
}

}  // namespace clearsky::server
