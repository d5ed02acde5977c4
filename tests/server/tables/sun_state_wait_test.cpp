// Per-sun preparation follows the table-build rule: a request waits up to build_wait, then gets
// 503 with Retry-After while the preparation goes on; a later request finds it ready.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "api/error/api_error.h"
#include "server/tables/table_store.h"
#include "tests/support/constant_sky_model.h"

namespace clearsky::server {
namespace {

std::atomic<int>& preparations() {
  static std::atomic<int> count{0};
  return count;
}

const ModelDescriptor& slow_sun_descriptor() {
  static const ModelDescriptor d{
      .id = "slowsun",
      .name = "Sky with a slow per-sun preparation",
      .version = "1",
      .citation = "tests/server/tables/sun_state_wait_test.cpp",
      .summary = "A constant sky whose per-sun state takes 400 ms.",
      .native_wavelengths_nm = {},
      .min_wavelength_nm = 360.0,
      .max_wavelength_nm = 830.0,
      .parameters = {},
      .capabilities = {.min_altitude_m = 0.0,
                       .max_altitude_m = 1000.0,
                       .max_sun_zenith_deg = 90.0,
                       .per_sun_precomputation = true},
  };
  return d;
}

// Keeps its prepared states, like the per-sun caches of Haber and Nishita96.
class SlowSunSky final : public testing::ConstantSky {
 public:
  explicit SlowSunSky(const ModelConfig& config) : ConstantSky(slow_sun_descriptor(), config) {}

 protected:
  std::shared_ptr<const SunState> compute_sun_state(const SunPosition& sun,
                                                    const PrecomputeContext&) const override {
    std::lock_guard lock(mutex_);
    if (!state_) {
      std::this_thread::sleep_for(std::chrono::milliseconds(3000));
      ++preparations();
      state_ = std::make_shared<const SunState>(sun);
    }
    return state_;
  }

 private:
  mutable std::mutex mutex_;
  mutable std::shared_ptr<const SunState> state_;
};

std::shared_ptr<const SkyModel> create_slow_sun(const ModelConfig& config,
                                                const PrecomputeContext&) {
  return std::make_shared<const SlowSunSky>(config);
}

TEST(SunStateWait, AnswersServiceUnavailableWhilePreparingThenServes) {
  TableStore::Options options;
  options.build_wait = std::chrono::milliseconds(20);
  options.retry_after_s = 6;
  TableStore store({ModelFactory{&slow_sun_descriptor(), &create_slow_sun, nullptr}}, options);
  // The model's own (empty) tables may also outlast the 20 ms wait on a loaded machine; only the
  // per-sun wait is under test, so wait for the model first.
  std::shared_ptr<const SkyModel> model;
  for (int i = 0; i < 1000 && !model; ++i) {
    try {
      model = store.model(store.factories()[0], ModelConfig{});
    } catch (const api::ApiError& e) {
      ASSERT_EQ(e.status(), 503);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  ASSERT_TRUE(model);
  const SunPosition sun{0.5, 1.0};
  const int before = preparations();
  const auto start = std::chrono::steady_clock::now();
  try {
    store.sun_state(model, sun);
    ADD_FAILURE() << "expected 503";
  } catch (const api::ApiError& e) {
    EXPECT_EQ(e.status(), 503);
    EXPECT_EQ(e.retry_after_s(), 6);
  }
  // The refusal comes after the wait, not after the preparation (3 s: margin for a loaded
  // machine).
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(2500));
  std::shared_ptr<const SunState> state;
  for (int i = 0; i < 1000 && !state; ++i) {
    try {
      state = store.sun_state(model, sun);
    } catch (const api::ApiError& e) {
      ASSERT_EQ(e.status(), 503);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  ASSERT_TRUE(state);
  EXPECT_EQ(state->sun().zenith_rad, 0.5);
  EXPECT_EQ(preparations() - before, 1);  // the background preparation was the only one
}

}  // namespace
}  // namespace clearsky::server
