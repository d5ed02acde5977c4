// SunStateCache: single flight (N threads asking for the same key -> one build), LRU bound,
// failed builds not cached; sun zenith buckets.
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

TEST(SunStateCache, AFailedBuildReachesItsWaitersAndIsNotCached) {
  SunStateCache<int> cache(2);
  EXPECT_THROW(cache.get_or_build(
                   "x", []() -> std::shared_ptr<const int> { throw std::runtime_error("no"); }),
               std::runtime_error);
  EXPECT_EQ(cache.size(), 0u);
  const auto v = cache.get_or_build("x", [] { return std::make_shared<const int>(7); });
  EXPECT_EQ(*v, 7);
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
