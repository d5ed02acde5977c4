// Standard tables built on first use (ModelFactory::standard_on_first_use,
// docs/quality-levels.md "Serving at once"): the default start builds list measured_aerosols'
// draft but not its standard, --prebuild lists exactly what it names; and in the store, the
// first standard request of a default not built at start, with its draft ready, is answered from
// the draft at once while the default's build starts (at the requests' priority), and from the
// default once that build is done. The standard build waits on a flag the test sets: nothing is
// timed.
#include <gtest/gtest.h>
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <optional>
#include <thread>

#include "models/registry.h"
#include "server/tables/start_builds.h"
#include "server/tables/table_store.h"
#include "tests/support/constant_sky_model.h"

namespace clearsky::server {
namespace {

bool lists(const std::vector<std::pair<const ModelFactory*, ModelConfig>>& builds,
           const std::string& id, const ModelConfig& config) {
  return std::any_of(builds.begin(), builds.end(), [&](const auto& b) {
    return b.first->descriptor->id == id &&
           b.second.canonical_string() == config.canonical_string();
  });
}

TEST(StartBuilds, MeasuredAerosolsStandardIsLeftForItsFirstUseByDefault) {
  const auto builds = start_builds(registered_models(), {});
  const ModelFactory& measured = *find_model("measured_aerosols");
  ASSERT_TRUE(measured.standard_on_first_use);
  EXPECT_TRUE(
      lists(builds, "measured_aerosols", level_config(*measured.descriptor, QualityLevel::draft)));
  EXPECT_FALSE(lists(builds, "measured_aerosols", ModelConfig{}));
  // Every other model's standard is built at start.
  for (const ModelFactory& f : registered_models()) {
    if (f.descriptor->id != "measured_aerosols") {
      EXPECT_FALSE(f.standard_on_first_use) << f.descriptor->id;
      EXPECT_TRUE(lists(builds, f.descriptor->id, ModelConfig{})) << f.descriptor->id;
    }
  }
  // --prebuild builds exactly what it lists, measured_aerosols' standard included.
  const auto listed = start_builds(registered_models(), {"measured_aerosols:standard"});
  ASSERT_EQ(listed.size(), 1u);
  EXPECT_TRUE(lists(listed, "measured_aerosols", ModelConfig{}));
}

const ModelDescriptor& first_use_descriptor() {
  static const ModelDescriptor d{
      .id = "firstuse",
      .name = "Sky whose standard is built on first use",
      .version = "1",
      .citation = "tests/server/tables/standard_on_first_use_test.cpp",
      .summary = "A constant sky; its standard build waits for the test.",
      .min_wavelength_nm = 360.0,
      .max_wavelength_nm = 830.0,
      .parameters = {{.name = "size", .default_value = 2, .min_value = 1, .max_value = 2}},
      .capabilities = {.max_altitude_m = 1000.0},
  };
  return d;
}

std::atomic<bool> release_standard{false};
std::atomic<int> standard_builds{0};
std::atomic<int> standard_policy{-1};

std::shared_ptr<const SkyModel> create_first_use(const ModelConfig& config,
                                                 const PrecomputeContext& context) {
  if (option_or_default(first_use_descriptor(), config, "size") == 2) {
    ++standard_builds;
    standard_policy = ::sched_getscheduler(0);
    while (!release_standard) {
      context.check_cancelled();
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  return std::make_shared<const testing::ConstantSky>(first_use_descriptor(), config);
}

TEST(StandardOnFirstUse, TheFirstStandardRequestIsAnsweredFromTheDraftWhileTheStandardBuilds) {
  TableStore::Options options;
  options.build_wait = std::chrono::milliseconds(1);
  ModelFactory factory{&first_use_descriptor(), &create_first_use, nullptr};
  factory.standard_on_first_use = true;
  TableStore store({factory}, options);
  const ModelFactory& f = store.factories()[0];
  ModelConfig draft;
  draft.options["size"] = 1;
  store.start_builds({{&f, draft}});
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(10);
  while (!store.ready() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  // Readiness waits for the start builds only: the standard was never asked for.
  ASSERT_TRUE(store.ready());
  EXPECT_FALSE(store.config_state(f, ModelConfig{}).has_value());
  EXPECT_EQ(standard_builds, 0);

  int fallback_calls = 0;
  const api::ModelProvider::FallbackConfig fallback = [&]() -> std::optional<ModelConfig> {
    ++fallback_calls;
    return draft;
  };
  const auto first = store.model_or_fallback(f, ModelConfig{}, fallback, {});
  EXPECT_TRUE(first.fallback);
  EXPECT_EQ(first.model->config().options.at("size"), 1.0);
  const auto state = store.config_state(f, ModelConfig{});
  ASSERT_TRUE(state.has_value());
  EXPECT_NE(state->status, api::ModelState::Status::ready);
  // Asked again meanwhile: the draft again, the one build still under way.
  EXPECT_TRUE(store.model_or_fallback(f, ModelConfig{}, fallback, {}).fallback);

  release_standard = true;
  TableStore::ServedModel served = first;
  while (served.fallback && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    served = store.model_or_fallback(f, ModelConfig{}, fallback, {});
  }
  EXPECT_FALSE(served.fallback);
  EXPECT_FALSE(served.model->config().options.contains("size"));
  // Once the standard tables are ready, the draft's configuration is not even made.
  const int calls_before_ready_requests = fallback_calls;
  EXPECT_FALSE(store.model_or_fallback(f, ModelConfig{}, fallback, {}).fallback);
  EXPECT_EQ(fallback_calls, calls_before_ready_requests);
  EXPECT_EQ(standard_builds, 1);
  // A build a request started: the requests' priority, not the background's.
  EXPECT_EQ(standard_policy, SCHED_OTHER);
  EXPECT_TRUE(store.ready());
}

}  // namespace
}  // namespace clearsky::server
