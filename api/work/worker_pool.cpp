// The bounded background workers (worker_pool.h).
#include "api/work/worker_pool.h"

#include <optional>

#include "api/error/api_error.h"

namespace clearsky::api {
namespace {

// The failure hook: the connection closed first, so that the next task opens a fresh one.
void fail(std::optional<storage::Database>& db, const WorkerTask& task, const std::string& error) {
  db.reset();
  if (!task.failed) return;
  try {
    task.failed(error);
  } catch (...) {
    // A hook's failure must not kill the worker.
  }
}

}  // namespace

WorkerPool::Reservation::~Reservation() {
  if (pool_ != nullptr) pool_->release();
}

WorkerPool::WorkerPool(OpenDatabase open_database, WorkerPoolOptions options)
    : open_database_(std::move(open_database)), options_(std::move(options)) {
  const unsigned workers = std::max(1u, options_.workers);
  for (unsigned i = 0; i < workers; ++i) threads_.emplace_back([this] { work(); });
}

WorkerPool::~WorkerPool() { stop(); }

WorkerPool::Reservation WorkerPool::reserve() {
  std::lock_guard lock(mutex_);
  if (stopping_)
    throw ApiError(503, "busy", "", "the server is stopping; try again later",
                   options_.retry_after_s);
  if (queue_.size() + reserved_ >= options_.max_queued)
    throw ApiError(
        503, "busy", "",
        std::to_string(queue_.size()) + " " + options_.task_noun + " are queued; try again later",
        options_.retry_after_s);
  ++reserved_;
  return Reservation(this);
}

void WorkerPool::release() {
  {
    std::lock_guard lock(mutex_);
    --reserved_;
  }
  idle_.notify_all();
}

std::int64_t WorkerPool::submit(Reservation reservation, WorkerTask task) {
  std::int64_t id = 0;
  {
    std::lock_guard lock(mutex_);
    reservation.pool_ = nullptr;  // its place becomes the queued task's
    --reserved_;
    id = next_id_++;
    queue_.push_back(Queued{id, std::move(task)});
  }
  wake_.notify_one();
  return id;
}

void WorkerPool::wait_idle() {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [this] { return queue_.empty() && reserved_ == 0 && running_ == 0; });
}

void WorkerPool::stop() {
  std::deque<Queued> dropped;
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    dropped.swap(queue_);
  }
  wake_.notify_all();
  idle_.notify_all();
  for (std::thread& t : threads_)
    if (t.joinable()) t.join();
  for (Queued& q : dropped) {
    if (!q.task.dropped) continue;
    try {
      q.task.dropped();
    } catch (...) {
      // A hook's failure must not stop the others (start-up marks what is left unfinished).
    }
  }
}

void WorkerPool::work() {
  std::optional<storage::Database> db;
  for (;;) {
    Queued q;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (stopping_) return;
      q = std::move(queue_.front());
      queue_.pop_front();
      ++running_;
    }
    try {
      if (q.task.started) q.task.started();
      if (!db) db.emplace(open_database_());
      q.task.run(*db);
    } catch (const std::exception& e) {
      fail(db, q.task, e.what());
    } catch (...) {
      fail(db, q.task, "unknown error");
    }
    {
      std::lock_guard lock(mutex_);
      --running_;
    }
    idle_.notify_all();
  }
}

}  // namespace clearsky::api
