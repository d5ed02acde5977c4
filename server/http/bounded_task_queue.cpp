// Worker threads over a bounded FIFO of connection tasks.
#include "server/http/bounded_task_queue.h"

#include <spdlog/spdlog.h>

namespace clearsky::server {

BoundedTaskQueue::BoundedTaskQueue(unsigned threads, std::size_t max_queued)
    : max_queued_(std::max<std::size_t>(1, max_queued)) {
  for (unsigned i = 0; i < std::max(1u, threads); ++i) workers_.emplace_back([this] { work(); });
}

BoundedTaskQueue::~BoundedTaskQueue() { shutdown(); }

void BoundedTaskQueue::enqueue(std::function<void()> task) {
  std::unique_lock lock(mutex_);
  not_full_.wait(lock, [&] { return shutting_down_ || tasks_.size() < max_queued_; });
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
  not_empty_.notify_one();
}

void BoundedTaskQueue::shutdown() {
  {
    std::lock_guard lock(mutex_);
    if (shutting_down_ && workers_.empty()) return;
    shutting_down_ = true;
  }
  not_empty_.notify_all();
  not_full_.notify_all();
  for (auto& w : workers_) {
    if (w.joinable()) w.join();
  }
  workers_.clear();
}

void BoundedTaskQueue::work() {
  while (true) {
    std::function<void()> task;
    {
      std::unique_lock lock(mutex_);
      not_empty_.wait(lock, [&] { return shutting_down_ || !tasks_.empty(); });
      if (tasks_.empty()) return;
      task = std::move(tasks_.front());
      tasks_.pop_front();
      not_full_.notify_one();
    }
    try {
      task();
    } catch (const std::exception& e) {
      spdlog::error("http worker: {}", e.what());
    } catch (...) {
      spdlog::error("http worker: unknown exception");
    }
  }
}

}  // namespace clearsky::server
