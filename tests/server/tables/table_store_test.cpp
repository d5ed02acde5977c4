// The table store: single-flight builds, 503 with Retry-After while building, readiness of the
// default tables, eviction of non-default configurations, and one entry for an option given at
// its default and the option left out.
#include "server/tables/table_store.h"

#include <gtest/gtest.h>

#include <thread>

#include "api/error/api_error.h"
#include "models/measured_aerosols/aerosol_inversion_source.h"
#include "models/measured_aerosols/measured_aerosols.h"
#include "tests/support/test_sky_model.h"

namespace clearsky::server {
namespace {

using clearsky::testing::test_factories;
using clearsky::testing::test_sky_builds;

ModelConfig with_options(std::map<std::string, double> options) {
  ModelConfig c;
  c.options = std::move(options);
  return c;
}

TEST(TableStore, ConcurrentRequestsShareOneBuild) {
  TableStore::Options options;
  options.build_wait = std::chrono::milliseconds(5000);
  TableStore store(test_factories(), options);
  const int before = test_sky_builds();
  const ModelConfig config = with_options({{"build_ms", 200}, {"gain", 1.5}});
  std::vector<std::thread> threads;
  std::vector<std::shared_ptr<const SkyModel>> got(8);
  for (int i = 0; i < 8; ++i) {
    threads.emplace_back([&, i] { got[i] = store.model(store.factories()[0], config); });
  }
  for (auto& t : threads) t.join();
  EXPECT_EQ(test_sky_builds() - before, 1);
  for (const auto& m : got) EXPECT_EQ(m, got[0]);
}

TEST(TableStore, AnswersServiceUnavailableWhileBuilding) {
  TableStore::Options options;
  options.build_wait = std::chrono::milliseconds(20);
  options.retry_after_s = 7;
  TableStore store(test_factories(), options);
  const ModelConfig config = with_options({{"build_ms", 400}});
  try {
    store.model(store.factories()[0], config);
    ADD_FAILURE() << "expected 503";
  } catch (const api::ApiError& e) {
    EXPECT_EQ(e.status(), 503);
    EXPECT_EQ(e.retry_after_s(), 7);
  }
  std::shared_ptr<const SkyModel> model;
  for (int i = 0; i < 100 && !model; ++i) {
    try {
      model = store.model(store.factories()[0], config);
    } catch (const api::ApiError& e) {
      ASSERT_EQ(e.status(), 503);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  ASSERT_TRUE(model);
}

TEST(TableStore, DefaultTablesMakeItReady) {
  TableStore store(test_factories(), {});
  EXPECT_FALSE(store.ready());
  store.start_default_builds();
  for (int i = 0; i < 200 && !store.ready(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_TRUE(store.ready());
  const api::ModelState state = store.default_state(store.factories()[0]);
  EXPECT_EQ(state.status, api::ModelState::Status::ready);
  EXPECT_EQ(state.table_bytes, 1234u);
  EXPECT_EQ(store.table_bytes().at("testsky"), 1234u);
}

TEST(TableStore, InvalidConfigurationsAreBadRequests) {
  TableStore store(test_factories(), {});
  try {
    store.model(store.factories()[0], with_options({{"gain", 100}}));
    ADD_FAILURE();
  } catch (const api::ApiError& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.parameter(), "gain");
  }
}

TEST(TableStore, EvictsLeastRecentlyUsedBeyondCapacity) {
  TableStore::Options options;
  options.capacity = 2;
  TableStore store(test_factories(), options);
  const auto& f = store.factories()[0];
  const int before = test_sky_builds();
  store.model(f, with_options({{"gain", 2}}));
  store.model(f, with_options({{"gain", 3}}));
  store.model(f, with_options({{"gain", 2}}));  // kept
  store.model(f, with_options({{"gain", 4}}));  // evicts gain 3, the least recently used
  EXPECT_EQ(test_sky_builds() - before, 3);
  store.model(f, with_options({{"gain", 2}}));
  EXPECT_EQ(test_sky_builds() - before, 3);
  store.model(f, with_options({{"gain", 3}}));
  EXPECT_EQ(test_sky_builds() - before, 4);
}

}  // namespace
}  // namespace clearsky::server

namespace clearsky::server {
namespace {

TEST(TableStore, OnDemandBuildsDoNotWaitBehindTheStartQueue) {
  // The default build (slow here) occupies the only builder; a request for another
  // configuration is built at once on its own thread.
  std::vector<ModelFactory> factories = clearsky::testing::test_factories();
  factories[0].create = [](const ModelConfig& config, const PrecomputeContext& context) {
    if (config.options.empty()) {  // the default configuration: 2 s, cancellable
      for (int i = 0; i < 200; ++i) {
        context.check_cancelled();
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
    }
    return clearsky::testing::create_test_sky(config, context);
  };
  TableStore::Options options;
  options.builder_threads = 1;
  options.build_wait = std::chrono::milliseconds(3000);
  TableStore store(factories, options);
  store.start_default_builds();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_EQ(store.default_state(store.factories()[0]).status,
            api::ModelState::Status::precomputing);
  const auto start = std::chrono::steady_clock::now();
  const auto model = store.model(store.factories()[0], with_options({{"gain", 3}}));
  EXPECT_TRUE(model);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  EXPECT_FALSE(store.ready());
}

}  // namespace
}  // namespace clearsky::server

namespace clearsky::server {
namespace {

TEST(TableStore, SunStatesComeFromTheModelsOwnPreparation) {
  // Per-sun models (Haber, Nishita96) share and bound their states in their own single-flight
  // cache (tests/models/core/sun_state_cache_test.cpp); the store adds no second cache.
  TableStore store(clearsky::testing::test_factories(), {});
  const auto model = store.model(store.factories()[0], with_options({{"gain", 2}}));
  const SunPosition a{0.3, 1.0}, b{0.3, 1.5};
  EXPECT_DOUBLE_EQ(store.sun_state(model, a)->sun().azimuth_rad, 1.0);
  EXPECT_DOUBLE_EQ(store.sun_state(model, b)->sun().azimuth_rad, 1.5);
  EXPECT_THROW(store.sun_state(model, SunPosition{3.0, 0.0}), std::invalid_argument)
      << "a sun the model refuses is refused through the store";
}

}  // namespace
}  // namespace clearsky::server

namespace clearsky::server {
namespace {

// An option given at its default selects the tables of the option left out: one entry, one
// build (models/core/canonical_config.h).
TEST(TableStore, AnOptionAtItsDefaultSharesTheEntryOfTheOptionLeftOut) {
  TableStore::Options options;
  options.build_wait = std::chrono::milliseconds(120000);
  TableStore store(test_factories(), options);
  const auto& f = store.factories()[0];
  const int before = test_sky_builds();
  const auto left_out = store.model(f, with_options({{"build_ms", 1}}));
  const auto at_default = store.model(f, with_options({{"build_ms", 1}, {"gain", 1.0}}));
  EXPECT_EQ(at_default, left_out);
  EXPECT_EQ(test_sky_builds() - before, 1);
  EXPECT_TRUE(store.config_state(f, with_options({{"build_ms", 1}, {"gain", 1.0}})));
  EXPECT_EQ(store.table_bytes().at("testsky"), 1234u);
}

// measured_aerosols with aerosols=0 (the shipped inversion) and without aerosols: one entry of
// the table store, whose tables are counted once.
TEST(TableStore, MeasuredAerosolsZeroIsTheOptionLeftOut) {
  TableStore::Options options;
  options.build_wait = std::chrono::milliseconds(120000);
  TableStore store({measured_aerosols_factory()}, options);
  const auto& f = store.factories()[0];
  // Small tables (a build well under a second), three wavelengths.
  ModelConfig left_out;
  left_out.wavelengths = WavelengthGrid::points({440.0, 550.0, 680.0});
  left_out.options = {{"scattering_orders", 2},
                      {"table_r_size", 8},
                      {"table_mu_size", 32},
                      {"table_mu_s_size", 8},
                      {"table_nu_size", 4}};
  ModelConfig zero = left_out;
  zero.options[kAerosolsOption] = 0;
  const auto first = store.model(f, zero);
  const auto second = store.model(f, left_out);
  EXPECT_EQ(second, first);
  EXPECT_EQ(store.table_bytes().at("measured_aerosols"), first->table_bytes());
}

}  // namespace
}  // namespace clearsky::server
