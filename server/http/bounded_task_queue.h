// cpp-httplib's worker pool with a bounded queue: a fixed number of worker threads and at
// most max_queued accepted connections waiting for one. When the queue is full, enqueue()
// (called by the accepting thread) waits, so further connections stay in the kernel's listen
// backlog instead of growing memory without bound. Thread-safe.
#pragma once

#include <httplib.h>

#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace clearsky::server {

class BoundedTaskQueue final : public httplib::TaskQueue {
 public:
  BoundedTaskQueue(unsigned threads, std::size_t max_queued);
  ~BoundedTaskQueue() override;
  void enqueue(std::function<void()> task) override;
  void shutdown() override;

 private:
  void work();

  std::size_t max_queued_;
  std::mutex mutex_;
  std::condition_variable not_empty_, not_full_;
  std::deque<std::function<void()>> tasks_;
  bool shutting_down_ = false;
  std::vector<std::thread> workers_;
};

}  // namespace clearsky::server
