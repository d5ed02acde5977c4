// Tests of the bounded worker pool shared by evaluations and imports (api/work/worker_pool.h):
// the queue bound (503 busy with Retry-After, reservations counted), one connection per
// worker kept across tasks and reset after a failure, the failure hook, dropped tasks on stop.
#include "api/work/worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <thread>

#include "api/error/api_error.h"

namespace clearsky::api {
namespace {

struct Opener {
  std::atomic<int> opened{0};
  WorkerPool::OpenDatabase function() {
    return [this] {
      ++opened;
      return storage::Database::open(":memory:");
    };
  }
};

TEST(WorkerPool, AFailedTaskResetsTheWorkersConnection) {
  Opener opener;
  WorkerPool pool(opener.function(), {1, 8, "tasks", 30});
  std::vector<std::string> failures;
  const auto task = [&](bool fail) {
    WorkerTask t;
    t.run = [fail](storage::Database& db) {
      db.execute("CREATE TABLE IF NOT EXISTS seen (x INTEGER)");
      if (fail) throw std::runtime_error("the database is locked");
    };
    t.failed = [&failures](const std::string& error) { failures.push_back(error); };
    return t;
  };
  pool.submit(task(false));
  pool.submit(task(false));
  pool.wait_idle();
  EXPECT_EQ(opener.opened, 1);  // one connection for both tasks
  pool.submit(task(true));
  pool.wait_idle();
  ASSERT_EQ(failures, std::vector<std::string>{"the database is locked"});
  pool.submit(task(false));
  pool.wait_idle();
  EXPECT_EQ(opener.opened, 2);  // the failure closed it: a fresh one
  EXPECT_EQ(failures.size(), 1u);
}

TEST(WorkerPool, AConnectionThatCannotOpenIsAFailure) {
  WorkerPool pool([]() -> storage::Database { throw std::runtime_error("no disk"); },
                  {1, 8, "tasks", 30});
  std::promise<std::string> failed;
  WorkerTask t;
  t.run = [](storage::Database&) { ADD_FAILURE() << "ran without a connection"; };
  t.failed = [&failed](const std::string& error) { failed.set_value(error); };
  pool.submit(std::move(t));
  EXPECT_EQ(failed.get_future().get(), "no disk");
}

TEST(WorkerPool, AFullQueueIsBusyAndStopDropsTheQueued) {
  Opener opener;
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  std::promise<void> running;
  auto pool =
      std::make_unique<WorkerPool>(opener.function(), WorkerPoolOptions{1, 2, "imports", 7});
  WorkerTask blocker;
  blocker.started = [&running] { running.set_value(); };
  blocker.run = [released](storage::Database&) { released.wait(); };
  const std::int64_t first = pool->submit(std::move(blocker));
  running.get_future().wait();  // the worker holds the first: the queue is empty
  std::atomic<int> dropped{0};
  std::atomic<int> ran{0};
  const auto counted = [&] {
    WorkerTask t;
    t.run = [&ran](storage::Database&) { ++ran; };
    t.dropped = [&dropped] { ++dropped; };
    return t;
  };
  const std::int64_t second = pool->submit(counted());
  EXPECT_EQ(second, first + 1);
  // A reservation holds a place as a queued task does.
  {
    WorkerPool::Reservation place = pool->reserve();
    try {
      pool->reserve();
      ADD_FAILURE() << "a third place was given";
    } catch (const ApiError& e) {
      EXPECT_EQ(e.status(), 503);
      EXPECT_EQ(e.code(), "busy");
      EXPECT_EQ(e.retry_after_s(), 7);
      EXPECT_NE(std::string(e.what()).find("1 imports are queued"), std::string::npos) << e.what();
    }
  }
  pool->submit(counted());  // the released place is free again
  EXPECT_THROW(pool->submit(counted()), ApiError);
  // Stopping: the running task ends, the two queued ones are dropped, not run.
  std::thread stopper([&] { pool->stop(); });
  // Released once stop() has taken the queue (it then refuses as "stopping", not "queued").
  for (bool stopping = false; !stopping;) {
    try {
      pool->reserve();
    } catch (const ApiError& e) {
      stopping = std::string(e.what()).find("stopping") != std::string::npos;
    }
    if (!stopping) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  release.set_value();
  stopper.join();
  EXPECT_EQ(ran, 0);
  EXPECT_EQ(dropped, 2);
  EXPECT_THROW(pool->reserve(), ApiError);  // stopped: refuses new work
  pool.reset();
}

}  // namespace
}  // namespace clearsky::api
