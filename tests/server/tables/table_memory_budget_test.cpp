// The table store's memory budget: tables kept or being built count against it (the pinned
// default included), least-recently-used unpinned configurations are evicted to make room for a
// new build, and a build that cannot fit is refused with 503 naming "table_memory".
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "api/error/api_error.h"
#include "server/tables/table_store.h"
#include "tests/support/test_sky_model.h"

namespace clearsky::server {
namespace {

using clearsky::testing::test_factories;

constexpr std::size_t kTestSkyBytes = 1234;  // TestSky::table_bytes()

ModelConfig with_gain(double gain, double build_ms = 0) {
  ModelConfig c;
  c.options = {{"gain", gain}, {"build_ms", build_ms}};
  return c;
}

// The default queued at start is built by a builder thread. A request that finds it already
// being built is answered 503 at once (a default build is long: table_store.h), so a test that
// asked at once raced with the builder: when the builder took the queue first (as under
// AddressSanitizer, where the test thread is slower), the request threw and the store's
// destructor then cancelled the build. The tests wait for readiness instead, as a client
// waits for /readyz.
void wait_until_ready(const TableStore& store) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!store.ready() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_TRUE(store.ready());
}

TEST(TableMemoryBudget, EvictsLeastRecentlyUsedToStayWithinBudget) {
  TableStore::Options options;
  options.memory_budget_bytes = 3 * kTestSkyBytes;  // the default and two more
  options.build_wait = std::chrono::seconds(60);    // a loaded machine: the builds finish first
  TableStore store(test_factories(), options);
  const ModelFactory& f = store.factories()[0];
  store.start_default_builds();
  wait_until_ready(store);
  store.model(f, ModelConfig{});
  const auto first = store.model(f, with_gain(1.5));
  store.model(f, with_gain(2.0));
  EXPECT_EQ(store.accounted_bytes(), 3 * kTestSkyBytes);
  store.model(f, with_gain(1.5));  // most recently used: 2.0 is now the oldest
  store.model(f, with_gain(3.0));
  EXPECT_LE(store.accounted_bytes(), options.memory_budget_bytes);
  EXPECT_EQ(store.model(f, with_gain(1.5)), first);  // kept
  EXPECT_TRUE(store.ready());                        // the default is never evicted
}

TEST(TableMemoryBudget, RefusesBuildsThatCannotFit) {
  TableStore::Options options;
  options.memory_budget_bytes = 2 * kTestSkyBytes;  // the default and one build
  options.build_wait = std::chrono::milliseconds(10);
  options.retry_after_s = 4;
  TableStore store(test_factories(), options);
  const ModelFactory& f = store.factories()[0];
  store.start_default_builds();
  wait_until_ready(store);
  store.model(f, ModelConfig{});
  // A slow build holds its estimate while it runs, so a second cannot start.
  EXPECT_THROW(store.model(f, with_gain(1.5, 2000)), api::ApiError);
  try {
    store.model(f, with_gain(2.5));
    ADD_FAILURE() << "expected 503";
  } catch (const api::ApiError& e) {
    EXPECT_EQ(e.status(), 503);
    EXPECT_EQ(e.parameter(), "table_memory");
    EXPECT_EQ(e.retry_after_s(), 4);
    EXPECT_NE(std::string(e.what()).find(std::to_string(2 * kTestSkyBytes)), std::string::npos)
        << e.what();
  }
  EXPECT_LE(store.accounted_bytes(), options.memory_budget_bytes);
}

TEST(TableMemoryBudget, DefaultsCountButAreNeverEvicted) {
  TableStore::Options options;
  options.memory_budget_bytes = kTestSkyBytes;  // only the default fits
  TableStore store(test_factories(), options);
  const ModelFactory& f = store.factories()[0];
  store.start_default_builds();
  wait_until_ready(store);
  const auto default_model = store.model(f, ModelConfig{});
  EXPECT_THROW(store.model(f, with_gain(1.5)), api::ApiError);
  EXPECT_EQ(store.model(f, ModelConfig{}), default_model);
  EXPECT_EQ(store.accounted_bytes(), kTestSkyBytes);
}

}  // namespace
}  // namespace clearsky::server

namespace clearsky::server {
namespace {

// A factory whose estimate grows with the option "gain" (kTestSkyBytes per unit): the store
// must admit or refuse on it before building anything.
std::size_t estimate_by_gain(const ModelConfig& config) {
  validate_config(clearsky::testing::test_sky_descriptor(), config);
  return static_cast<std::size_t>(
      option_or_default(clearsky::testing::test_sky_descriptor(), config, "gain") *
      static_cast<double>(kTestSkyBytes));
}

TEST(TableMemoryBudget, RefusesOnTheModelsEstimateBeforeBuildingAndCountsRealBytesAfter) {
  TableStore::Options options;
  options.memory_budget_bytes = 4 * kTestSkyBytes;
  options.build_wait = std::chrono::seconds(60);
  options.retry_after_s = 3;
  TableStore store({ModelFactory{&clearsky::testing::test_sky_descriptor(),
                                 &clearsky::testing::create_test_sky, &estimate_by_gain}},
                   options);
  const ModelFactory& f = store.factories()[0];
  store.start_default_builds();
  wait_until_ready(store);
  EXPECT_EQ(store.accounted_bytes(), kTestSkyBytes);
  // Estimated at 5 x 1234 bytes: refused without a build, although no table of that size was
  // ever built (the former rule, the largest built so far, would have admitted it). Beside the
  // pinned default it could never fit in 4 x 1234 bytes: 413, no Retry-After.
  const int builds_before = clearsky::testing::test_sky_builds().load();
  try {
    store.model(f, with_gain(5.0));
    ADD_FAILURE() << "expected 413";
  } catch (const api::ApiError& e) {
    EXPECT_EQ(e.status(), 413);
    EXPECT_EQ(e.code(), "too_large");
    EXPECT_EQ(e.parameter(), "table_memory");
    EXPECT_EQ(e.retry_after_s(), 0);
    EXPECT_NE(std::string(e.what()).find(std::to_string(5 * kTestSkyBytes)), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("--table-memory"), std::string::npos) << e.what();
  }
  EXPECT_EQ(clearsky::testing::test_sky_builds().load(), builds_before);
  EXPECT_EQ(store.accounted_bytes(), kTestSkyBytes);
  // Estimated at 2.5 x 1234 bytes: admitted; once built it counts its real 1234 bytes.
  store.model(f, with_gain(2.5));
  EXPECT_EQ(clearsky::testing::test_sky_builds().load(), builds_before + 1);
  EXPECT_EQ(store.accounted_bytes(), 2 * kTestSkyBytes);
}

}  // namespace
}  // namespace clearsky::server
