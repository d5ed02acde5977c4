// One copy of equal tables in memory (models/bruneton/shared_tables.h): Elek and Bruneton of
// one configuration share their tables while either lives, concurrent builds of equal tables
// build once, tables go with the last model that holds them, and a fresh build
// (PrecomputeContext::reuse_live_tables false) shares nothing.
#include <gtest/gtest.h>

#include <thread>

#include "models/bruneton/bruneton.h"
#include "models/registry.h"
#include "tests/models/bruneton/bruneton_test_support.h"

namespace clearsky {
namespace {

// Wavelengths no other test of this program uses, so that no model alive elsewhere in the
// program holds these tables.
ModelConfig shared_config() {
  ModelConfig c = testing::small_bruneton_config(2);
  c.wavelengths = WavelengthGrid::points({471.0, 612.0});
  c.options["table_r_size"] = 4;
  c.options["table_mu_size"] = 8;
  c.options["table_mu_s_size"] = 4;
  c.options["table_nu_size"] = 2;
  return c;
}

std::shared_ptr<const BrunetonModel> create(const char* id, const ModelConfig& config,
                                            const PrecomputeContext& context) {
  auto model =
      std::dynamic_pointer_cast<const BrunetonModel>(find_model(id)->create(config, context));
  if (model == nullptr) throw std::logic_error("not a Bruneton model");
  return model;
}

TEST(BrunetonTablesInMemory, ElekAndBrunetonOfOneConfigurationShareOneCopy) {
  testing::MemoryTableCache cache;
  PrecomputeContext context;
  context.cache = &cache;
  const auto bruneton = create("bruneton", shared_config(), context);
  const auto elek = create("elek", shared_config(), context);
  EXPECT_EQ(&bruneton->tables(), &elek->tables());
  EXPECT_FALSE(bruneton->shares_tables());
  EXPECT_TRUE(elek->shares_tables());
  EXPECT_FALSE(elek->loaded_from_cache());
  // One look in the cache (a miss), one precomputation stored: Elek asked for nothing.
  EXPECT_EQ(cache.loads, 1);
  EXPECT_EQ(cache.stores, 1);
  EXPECT_EQ(elek->descriptor().id, "elek");

  // Other tables are not shared: another atmosphere, another resolution.
  ModelConfig thicker = shared_config();
  thicker.atmosphere.angstrom_beta = 0.1;
  EXPECT_NE(&create("elek", thicker, context)->tables(), &bruneton->tables());
  ModelConfig finer = shared_config();
  finer.options["table_nu_size"] = 4;
  EXPECT_NE(&create("bruneton", finer, context)->tables(), &bruneton->tables());
}

TEST(BrunetonTablesInMemory, TablesGoWithTheLastModelHoldingThem) {
  testing::MemoryTableCache cache;
  PrecomputeContext context;
  context.cache = &cache;
  create("bruneton", shared_config(), context).reset();
  // Nothing holds them any more: the next model reads the cache, it shares nothing.
  const auto again = create("elek", shared_config(), context);
  EXPECT_FALSE(again->shares_tables());
  EXPECT_TRUE(again->loaded_from_cache());
  EXPECT_EQ(cache.stores, 1);
}

TEST(BrunetonTablesInMemory, ConcurrentBuildsOfEqualTablesBuildOnce) {
  testing::MemoryTableCache cache;
  PrecomputeContext context;
  context.cache = &cache;
  std::shared_ptr<const BrunetonModel> bruneton, elek;
  std::thread first([&] { bruneton = create("bruneton", shared_config(), context); });
  std::thread second([&] { elek = create("elek", shared_config(), context); });
  first.join();
  second.join();
  ASSERT_NE(bruneton, nullptr);
  ASSERT_NE(elek, nullptr);
  EXPECT_EQ(&bruneton->tables(), &elek->tables());
  EXPECT_NE(bruneton->shares_tables(), elek->shares_tables());
  EXPECT_EQ(cache.stores, 1);
}

TEST(BrunetonTablesInMemory, AFreshBuildSharesNothing) {
  PrecomputeContext context;
  const auto bruneton = create("bruneton", shared_config(), context);
  PrecomputeContext fresh;
  fresh.reuse_live_tables = false;
  const auto elek = create("elek", shared_config(), fresh);
  EXPECT_NE(&bruneton->tables(), &elek->tables());
  EXPECT_FALSE(elek->shares_tables());
  EXPECT_EQ(elek->tables().single_mie.values, bruneton->tables().single_mie.values);
}

TEST(BrunetonTablesInMemory, AWaiterSeesItsOwnCancellation) {
  // A build of these tables is under way (cancelled only when the test ends); a second model
  // waiting for it gives up when its own context is cancelled.
  std::atomic<bool> stop_first{false};
  PrecomputeContext slow;
  slow.cancel = &stop_first;
  std::atomic<bool> started{false};
  slow.progress = [&](double, std::string_view) {
    started = true;
    while (!stop_first) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  };
  ModelConfig config = shared_config();
  config.atmosphere.angstrom_beta = 0.3;  // tables of this test only
  std::thread first([&] { EXPECT_THROW(create("bruneton", config, slow), PrecomputeCancelled); });
  while (!started) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  std::atomic<bool> stop_second{true};
  PrecomputeContext waiter;
  waiter.cancel = &stop_second;
  EXPECT_THROW(create("elek", config, waiter), PrecomputeCancelled);
  stop_first = true;
  first.join();
  // The failed build left nothing behind: the next model builds.
  EXPECT_FALSE(create("elek", config, {})->shares_tables());
}

}  // namespace
}  // namespace clearsky
