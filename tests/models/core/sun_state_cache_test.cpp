// SunStateCache: single flight (N threads asking for the same key -> one build), LRU bounds in
// count and in bytes, failed builds not cached; sun zenith buckets.
#include "models/core/sun_state_cache.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "models/core/numeric.h"

namespace clearsky {
namespace {

TEST(SunStateCache, ConcurrentRequestsForOneKeyShareOneBuild) {
  SunStateCache<int> cache(4);
  std::atomic<int> builds{0};
  std::atomic<int> started{0};
  constexpr int kThreads = 8;
  std::vector<std::shared_ptr<const int>> results(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      ++started;
      while (started.load() < kThreads) std::this_thread::yield();
      results[t] = cache.get_or_build("sun=30", [&] {
        ++builds;
        // Long enough that every other thread asks while this build is in flight.
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        return std::make_shared<const int>(42);
      });
    });
  }
  for (auto& thread : threads) thread.join();
  EXPECT_EQ(builds.load(), 1);
  for (const auto& r : results) {
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(r.get(), results[0].get());  // the very same immutable state
    EXPECT_EQ(*r, 42);
  }
  EXPECT_EQ(cache.stats().builds, 1u);
  EXPECT_EQ(cache.stats().hits, static_cast<std::size_t>(kThreads - 1));
}

TEST(SunStateCache, KeepsAtMostCapacityEntriesDroppingTheLeastRecentlyUsed) {
  SunStateCache<int> cache(2);
  int builds = 0;
  const auto build = [&](int v) {
    return [&builds, v] {
      ++builds;
      return std::make_shared<const int>(v);
    };
  };
  const auto a = cache.get_or_build("a", build(1));
  cache.get_or_build("b", build(2));
  cache.get_or_build("a", build(1));  // a is now the most recent
  cache.get_or_build("c", build(3));  // drops b
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_EQ(builds, 3);
  cache.get_or_build("a", build(1));
  EXPECT_EQ(builds, 3);
  cache.get_or_build("b", build(2));
  EXPECT_EQ(builds, 4);
  EXPECT_EQ(*a, 1);  // a holder keeps its state alive whatever the cache drops
  EXPECT_GE(cache.stats().evictions, 2u);
}

// A state that reports its size, like HaberDome and nishita96::SunTables.
struct SizedState {
  std::size_t bytes;
  std::size_t memory_bytes() const { return bytes; }
};

TEST(SunStateCache, KeepsAtMostMaxBytesDroppingTheLeastRecentlyUsed) {
  SunStateCache<SizedState> cache(100, 1000);  // the count bound is not the one that bites
  int builds = 0;
  const auto build = [&](std::size_t bytes) {
    return [&builds, bytes] {
      ++builds;
      return std::make_shared<const SizedState>(SizedState{bytes});
    };
  };
  cache.get_or_build("a", build(400));
  cache.get_or_build("b", build(400));
  EXPECT_EQ(cache.stats().bytes, 800u);
  cache.get_or_build("a", build(400));  // a is now the most recent
  cache.get_or_build("c", build(400));  // 1200 bytes: drops b, the least recently used
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_EQ(cache.stats().bytes, 800u);
  EXPECT_EQ(cache.stats().evictions, 1u);
  EXPECT_EQ(builds, 3);
  cache.get_or_build("a", build(400));
  cache.get_or_build("c", build(400));
  EXPECT_EQ(builds, 3);
  cache.get_or_build("b", build(400));  // built again
  EXPECT_EQ(builds, 4);
  EXPECT_LE(cache.stats().bytes, cache.max_bytes());
  // A state above the bound alone is kept (its requester uses it), everything else dropped.
  const auto big = cache.get_or_build("big", build(5000));
  EXPECT_EQ(cache.size(), 1u);
  EXPECT_EQ(cache.stats().bytes, 5000u);
  EXPECT_EQ(cache.get_or_build("big", build(5000)), big);
  EXPECT_EQ(builds, 5);
  // The next state drops it.
  cache.get_or_build("d", build(100));
  EXPECT_EQ(cache.size(), 1u);
  EXPECT_EQ(cache.stats().bytes, 100u);
}

TEST(SunStateCache, AFailedBuildReachesItsWaitersAndIsNotCached) {
  SunStateCache<int> cache(2);
  EXPECT_THROW(cache.get_or_build(
                   "x", []() -> std::shared_ptr<const int> { throw std::runtime_error("no"); }),
               std::runtime_error);
  EXPECT_EQ(cache.size(), 0u);
  const auto v = cache.get_or_build("x", [] { return std::make_shared<const int>(7); });
  EXPECT_EQ(*v, 7);
}

// keep = false (PrecomputeContext::keep_sun_state: the server's pass over the day's states)
// returns the state it built without keeping it, and does not make a kept state more recent.
TEST(SunStateCache, AStateBuiltWithoutKeepIsReturnedButNotKept) {
  SunStateCache<int> cache(2);
  int builds = 0;
  const auto build = [&] { return std::make_shared<const int>(++builds); };
  EXPECT_EQ(*cache.get_or_build("a", build, false), 1);
  EXPECT_EQ(cache.size(), 0u);
  EXPECT_EQ(cache.stats().bytes, 0u);
  EXPECT_EQ(*cache.get_or_build("a", build), 2);  // built again, now kept
  EXPECT_EQ(*cache.get_or_build("b", build), 3);
  EXPECT_EQ(*cache.get_or_build("a", build, false), 2);  // a hit, left least recently used
  EXPECT_EQ(*cache.get_or_build("c", build), 4);         // drops a, not b
  EXPECT_EQ(*cache.get_or_build("b", build), 3);
  EXPECT_EQ(*cache.get_or_build("a", build), 5);
  EXPECT_EQ(builds, 5);
}

TEST(SunStateCache, BucketCentresAreMultiplesOfTheWidthInsideZeroToPi) {
  const double w = degrees_to_radians(1.0);
  EXPECT_DOUBLE_EQ(sun_zenith_bucket_centre(degrees_to_radians(30.4), w), 30.0 * w);
  EXPECT_DOUBLE_EQ(sun_zenith_bucket_centre(degrees_to_radians(30.6), w), 31.0 * w);
  EXPECT_DOUBLE_EQ(sun_zenith_bucket_centre(0.3, 0.0), 0.3);
  EXPECT_LE(sun_zenith_bucket_centre(kPi, degrees_to_radians(7.0)), kPi);
  EXPECT_GE(sun_zenith_bucket_centre(0.0, degrees_to_radians(7.0)), 0.0);
}

}  // namespace
}  // namespace clearsky
