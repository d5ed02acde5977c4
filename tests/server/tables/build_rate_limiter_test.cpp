// The per-client build rate: the sliding window of server/tables/build_rate_limiter.h on its
// own (times given, no sleeping), and the table store answering 429 naming "build_rate" to the
// client beyond it while other clients and the server's own work go on.
#include "server/tables/build_rate_limiter.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "api/error/api_error.h"
#include "server/tables/table_store.h"
#include "tests/support/test_sky_model.h"

namespace clearsky::server {
namespace {

using std::chrono::seconds;

TEST(BuildRateLimiter, AllowsBuildsPerWindowThenTellsWhenTheOldestLeavesIt) {
  BuildRateLimiter limiter(2, seconds(60));
  const auto t0 = BuildRateLimiter::Clock::time_point{} + std::chrono::hours(1);
  EXPECT_EQ(limiter.seconds_until_allowed("10.0.0.1", t0), 0);
  limiter.record("10.0.0.1", t0);
  limiter.record("10.0.0.1", t0 + seconds(10));
  EXPECT_EQ(limiter.seconds_until_allowed("10.0.0.1", t0 + seconds(20)), 40);
  // Another client has its own window; the server's own work (no address) is not limited.
  EXPECT_EQ(limiter.seconds_until_allowed("10.0.0.2", t0 + seconds(20)), 0);
  EXPECT_EQ(limiter.seconds_until_allowed("", t0 + seconds(20)), 0);
  // The first build leaves the window at t0 + 60 s: one more is allowed, then the second's
  // departure is awaited.
  EXPECT_EQ(limiter.seconds_until_allowed("10.0.0.1", t0 + seconds(61)), 0);
  limiter.record("10.0.0.1", t0 + seconds(61));
  EXPECT_EQ(limiter.seconds_until_allowed("10.0.0.1", t0 + seconds(62)), 8);
  // Clients whose builds all left the window are forgotten.
  EXPECT_EQ(limiter.seconds_until_allowed("10.0.0.3", t0 + seconds(200)), 0);
  EXPECT_EQ(limiter.clients(), 0u);
}

TEST(BuildRateLimiter, ZeroMeansNoLimit) {
  BuildRateLimiter limiter(0, seconds(60));
  const auto t0 = BuildRateLimiter::Clock::time_point{} + std::chrono::hours(1);
  for (int i = 0; i < 100; ++i) limiter.record("10.0.0.1", t0);
  EXPECT_EQ(limiter.seconds_until_allowed("10.0.0.1", t0), 0);
  EXPECT_EQ(limiter.clients(), 0u);
}

ModelConfig with_gain(double gain) {
  ModelConfig c;
  c.options = {{"gain", gain}};
  return c;
}

TEST(BuildRateLimiter, TheTableStoreRefusesTheClientBeyondItsRateWith429) {
  TableStore::Options options;
  options.build_rate = 2;
  options.build_rate_window = std::chrono::hours(1);
  options.build_wait = std::chrono::seconds(60);
  TableStore store(clearsky::testing::test_factories(), options);
  const ModelFactory& f = store.factories()[0];
  const api::ModelRequester client{"192.0.2.7"};
  store.model(f, with_gain(1.5), client);
  store.model(f, with_gain(2.0), client);
  // Built configurations are no builds: asked again, they are answered.
  store.model(f, with_gain(1.5), client);
  const int builds_before = clearsky::testing::test_sky_builds().load();
  try {
    store.model(f, with_gain(2.5), client);
    ADD_FAILURE() << "expected 429";
  } catch (const api::ApiError& e) {
    EXPECT_EQ(e.status(), 429);
    EXPECT_EQ(e.code(), "too_many_builds");
    EXPECT_EQ(e.parameter(), "build_rate");
    EXPECT_GT(e.retry_after_s(), 3000);  // the window is an hour, the builds seconds old
    EXPECT_LE(e.retry_after_s(), 3600);
    EXPECT_NE(std::string(e.what()).find("192.0.2.7"), std::string::npos) << e.what();
  }
  EXPECT_EQ(clearsky::testing::test_sky_builds().load(), builds_before);
  // Another client, and the server's own work, still build.
  store.model(f, with_gain(2.5), api::ModelRequester{"192.0.2.8"});
  store.model(f, with_gain(3.0));
  EXPECT_EQ(clearsky::testing::test_sky_builds().load(), builds_before + 2);
}

}  // namespace
}  // namespace clearsky::server
