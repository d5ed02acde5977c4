// Background table work at the lowest CPU priority (server/tables/background_priority.h,
// docs/tables-and-memory.md "Background work"): a configuration queued by TableStore::prebuild
// is built under SCHED_IDLE, and so are the threads its precomputation starts; a start build
// and a build a request starts keep the normal priority, as does the thread that asked. The pass
// over the day's per-sun states prepares its states under SCHED_IDLE and leaves them out of the
// model's memory (PrecomputeContext::keep_sun_state). The policy is read back with
// sched_getscheduler(0) inside the builds: nothing is timed.
#include "server/tables/background_priority.h"

#include <gtest/gtest.h>
#include <sched.h>

#include <chrono>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include "server/tables/day_sun_states.h"
#include "server/tables/table_store.h"
#include "tests/support/constant_sky_model.h"

namespace clearsky::server {
namespace {

// Per value of the option "tag": the policy of the build's thread and of a worker thread it
// started.
struct Policies {
  int build = -1;
  int worker = -1;
};
std::mutex policies_mutex;
std::map<int, Policies>& build_policies() {
  static std::map<int, Policies> policies;
  return policies;
}

const ModelDescriptor& recording_descriptor() {
  static const ModelDescriptor d{
      .id = "recording",
      .name = "Sky that records its builds' scheduling policy",
      .version = "1",
      .citation = "tests/server/tables/background_priority_test.cpp",
      .summary = "A constant sky.",
      .min_wavelength_nm = 360.0,
      .max_wavelength_nm = 830.0,
      .parameters = {{.name = "tag", .default_value = 0, .min_value = 0, .max_value = 10}},
      .capabilities = {.max_altitude_m = 1000.0},
  };
  return d;
}

std::shared_ptr<const SkyModel> create_recording(const ModelConfig& config,
                                                 const PrecomputeContext&) {
  Policies p;
  p.build = ::sched_getscheduler(0);
  std::thread worker([&p] { p.worker = ::sched_getscheduler(0); });
  worker.join();
  std::lock_guard lock(policies_mutex);
  build_policies()[static_cast<int>(option_or_default(recording_descriptor(), config, "tag"))] = p;
  return std::make_shared<const testing::ConstantSky>(recording_descriptor(), config);
}

ModelConfig tagged(int tag) {
  ModelConfig config;
  config.options["tag"] = tag;
  return config;
}

bool ready(const TableStore& store, const ModelFactory& factory, const ModelConfig& config) {
  const auto state = store.config_state(factory, config);
  return state && state->status == api::ModelState::Status::ready;
}

TEST(BackgroundPriority, PrebuiltTablesBuildAtIdlePriorityStartAndRequestedOnesDoNot) {
  TableStore::Options options;
  options.builder_threads = 1;
  options.build_wait = std::chrono::minutes(5);
  TableStore store({ModelFactory{&recording_descriptor(), &create_recording, nullptr}}, options);
  const ModelFactory& f = store.factories()[0];
  store.start_builds({{&f, tagged(1)}});
  store.prebuild(f, tagged(2));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(10);
  while ((!ready(store, f, tagged(1)) || !ready(store, f, tagged(2))) &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(ready(store, f, tagged(1)) && ready(store, f, tagged(2)));
  // A request's build: launched on its own thread, awaited within build_wait.
  ASSERT_TRUE(store.model(f, tagged(3)));

  std::lock_guard lock(policies_mutex);
  const auto& p = build_policies();
  EXPECT_EQ(p.at(1).build, SCHED_OTHER);
  EXPECT_EQ(p.at(1).worker, SCHED_OTHER);
  EXPECT_EQ(p.at(2).build, SCHED_IDLE);
  EXPECT_EQ(p.at(2).worker, SCHED_IDLE);  // inherited by the precomputation's threads
  EXPECT_EQ(p.at(3).build, SCHED_OTHER);
  EXPECT_EQ(p.at(3).worker, SCHED_OTHER);
  EXPECT_EQ(::sched_getscheduler(0), SCHED_OTHER);  // the builder left this thread as it was
}

TEST(BackgroundPriority, RunAtIdlePriorityKeepsTheCallersPolicyAndRethrows) {
  int inside = -1;
  run_at_idle_priority([&] { inside = ::sched_getscheduler(0); });
  EXPECT_EQ(inside, SCHED_IDLE);
  EXPECT_EQ(::sched_getscheduler(0), SCHED_OTHER);
  EXPECT_THROW(run_at_idle_priority([] { throw std::runtime_error("x"); }), std::runtime_error);
}

// A per-sun model with sun buckets of 5 degrees, dark beyond 10: the pass prepares 3 buckets.
struct SunRecord {
  int thread = -1;
  int worker = -1;
  bool keep = true;
};
std::vector<SunRecord>& sun_records() {
  static std::vector<SunRecord> records;
  return records;
}

const ModelDescriptor& bucketed_descriptor() {
  static const ModelDescriptor d{
      .id = "bucketed",
      .name = "Sky with per-sun states in sun buckets",
      .version = "1",
      .citation = "tests/server/tables/background_priority_test.cpp",
      .summary = "A constant sky whose per-sun preparation records its thread's policy.",
      .min_wavelength_nm = 360.0,
      .max_wavelength_nm = 830.0,
      .parameters =
          {{.name = "sun_zenith_bucket_deg", .default_value = 5, .min_value = 0, .max_value = 10}},
      .capabilities = {.max_altitude_m = 1000.0,
                       .max_sun_zenith_deg = 90.0,
                       .dark_beyond_sun_zenith_deg = 10.0,
                       .per_sun_precomputation = true},
  };
  return d;
}

class BucketedSky final : public testing::ConstantSky {
 public:
  explicit BucketedSky(const ModelConfig& config) : ConstantSky(bucketed_descriptor(), config) {}

 protected:
  std::shared_ptr<const SunState> compute_sun_state(
      const SunPosition& sun, const PrecomputeContext& context) const override {
    SunRecord record;
    record.thread = ::sched_getscheduler(0);
    record.keep = context.keep_sun_state;
    // A thread the preparation starts, as a precomputation's workers are (parallel_for).
    std::thread worker([&record] { record.worker = ::sched_getscheduler(0); });
    worker.join();
    std::lock_guard lock(policies_mutex);
    sun_records().push_back(record);
    return std::make_shared<const SunState>(sun);
  }
};

std::shared_ptr<const SkyModel> create_bucketed(const ModelConfig& config,
                                                const PrecomputeContext&) {
  return std::make_shared<const BucketedSky>(config);
}

TEST(BackgroundPriority, TheDaySunStatesPassRunsAtIdlePriorityAndKeepsNoState) {
  TableStore store({ModelFactory{&bucketed_descriptor(), &create_bucketed, nullptr}}, {});
  const ModelFactory& f = store.factories()[0];
  const std::vector<std::pair<const ModelFactory*, ModelConfig>> builds = {{&f, ModelConfig{}}};
  store.start_builds(builds);
  DaySunStates pass(store, builds, nullptr);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(10);
  auto finished = [&] {
    const auto progress = pass.progress();
    return progress.at("bucketed").built == progress.at("bucketed").total;
  };
  while (!finished() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(finished());
  EXPECT_EQ(pass.progress().at("bucketed").total, 3u);
  std::lock_guard lock(policies_mutex);
  ASSERT_EQ(sun_records().size(), 3u);
  for (const SunRecord& r : sun_records()) {
    EXPECT_EQ(r.thread, SCHED_IDLE);
    EXPECT_EQ(r.worker, SCHED_IDLE);
    EXPECT_FALSE(r.keep);
  }
  EXPECT_EQ(::sched_getscheduler(0), SCHED_OTHER);
}

}  // namespace
}  // namespace clearsky::server
