// A thread's last per-sun states: found for the same live model and the same sun bit for bit,
// never for another model (even one made at a freed model's address), the oldest dropped
// beyond kSlots, large states not kept; TableStore::sun_state prepares a repeated sun once.
#include "server/tables/recent_sun_states.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "server/tables/table_store.h"
#include "tests/support/constant_sky_model.h"

namespace clearsky::server {
namespace {

const ModelDescriptor& counted_descriptor() {
  static const ModelDescriptor d{
      .id = "countedsun",
      .name = "Sky counting its per-sun states",
      .version = "1",
      .citation = "tests/server/tables/recent_sun_states_test.cpp",
      .summary = "A constant sky whose per-sun states are counted.",
      .native_wavelengths_nm = {},
      .min_wavelength_nm = 360.0,
      .max_wavelength_nm = 830.0,
      .parameters = {},
      .capabilities = {.min_altitude_m = 0.0, .max_altitude_m = 1000.0},
  };
  return d;
}

std::atomic<int>& states_made() {
  static std::atomic<int> count{0};
  return count;
}

// A state of a chosen size (memory_bytes), as Hosek's (about 7 kB) or a larger one.
class SizedState final : public SunState {
 public:
  SizedState(const SunPosition& sun, std::size_t bytes) : SunState(sun), bytes_(bytes) {}
  std::size_t memory_bytes() const override { return bytes_; }

 private:
  std::size_t bytes_;
};

class CountedSky final : public testing::ConstantSky {
 public:
  explicit CountedSky(const ModelConfig& config, std::size_t state_bytes = 7000)
      : ConstantSky(counted_descriptor(), config), state_bytes_(state_bytes) {}

 protected:
  std::shared_ptr<const SunState> compute_sun_state(const SunPosition& sun,
                                                    const PrecomputeContext&) const override {
    ++states_made();
    return std::make_shared<const SizedState>(sun, state_bytes_);
  }

 private:
  std::size_t state_bytes_;
};

std::shared_ptr<const SkyModel> create_counted(const ModelConfig& config,
                                               const PrecomputeContext&) {
  return std::make_shared<const CountedSky>(config);
}

TEST(RecentSunStates, FindsTheStateKeptForTheSameModelAndSun) {
  RecentSunStates recent;
  const auto model = std::make_shared<const CountedSky>(ModelConfig{});
  const SunPosition sun{0.5, 1.0};
  EXPECT_EQ(recent.find(model, sun), nullptr);
  const auto state = model->prepare_sun(sun);
  recent.keep(model, sun, state);
  EXPECT_EQ(recent.find(model, sun), state);
  EXPECT_EQ(recent.find(model, SunPosition{0.5, 1.0 + 1e-15}), nullptr);
  EXPECT_EQ(recent.find(model, SunPosition{0.5000001, 1.0}), nullptr);
  // -0 and +0 are different suns (their sines differ in sign).
  recent.keep(model, SunPosition{0.5, 0.0}, model->prepare_sun(SunPosition{0.5, 0.0}));
  EXPECT_NE(recent.find(model, SunPosition{0.5, 0.0}), nullptr);
  EXPECT_EQ(recent.find(model, SunPosition{0.5, -0.0}), nullptr);
  // Another model of the same configuration has states of its own.
  const auto other = std::make_shared<const CountedSky>(ModelConfig{});
  EXPECT_EQ(recent.find(other, sun), nullptr);
}

TEST(RecentSunStates, NeverMatchesAModelMadeWhereAFreedOneWas) {
  RecentSunStates recent;
  const SunPosition sun{0.3, 2.0};
  auto model = std::make_shared<const CountedSky>(ModelConfig{});
  recent.keep(model, sun, model->prepare_sun(sun));
  const SkyModel* address = model.get();
  model.reset();
  // Models of the same size are made until one lands at the freed address (the allocator
  // usually gives it back at once); whether or not one does, none may find the old state.
  std::vector<std::shared_ptr<const SkyModel>> made;
  bool reused = false;
  for (int i = 0; i < 64 && !reused; ++i) {
    made.push_back(std::make_shared<const CountedSky>(ModelConfig{}));
    reused = made.back().get() == address;
    EXPECT_EQ(recent.find(made.back(), sun), nullptr);
  }
}

TEST(RecentSunStates, DropsTheOldestBeyondItsSlotsAndSkipsLargeStates) {
  RecentSunStates recent;
  const auto model = std::make_shared<const CountedSky>(ModelConfig{});
  std::vector<SunPosition> suns;
  for (std::size_t i = 0; i <= RecentSunStates::kSlots; ++i) {
    suns.push_back({0.1 * static_cast<double>(i + 1), 0.0});
    recent.keep(model, suns.back(), model->prepare_sun(suns.back()));
  }
  EXPECT_EQ(recent.find(model, suns.front()), nullptr);
  for (std::size_t i = 1; i < suns.size(); ++i) EXPECT_NE(recent.find(model, suns[i]), nullptr);

  const SunPosition sun{1.2, 0.5};
  const auto large = std::make_shared<const SizedState>(sun, RecentSunStates::kMaxStateBytes + 1);
  recent.keep(model, sun, large);
  EXPECT_EQ(recent.find(model, sun), nullptr);
}

TEST(RecentSunStates, TableStorePreparesARepeatedSunOncePerThread) {
  TableStore store({ModelFactory{&counted_descriptor(), &create_counted, nullptr}},
                   TableStore::Options{});
  const auto model = store.model(store.factories()[0], ModelConfig{});
  const SunPosition sun{0.7, 0.25};
  const int before = states_made();
  const auto first = store.sun_state(model, sun);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(store.sun_state(model, sun), first);
  EXPECT_EQ(states_made() - before, 1);
  // Another thread keeps its own.
  std::shared_ptr<const SunState> elsewhere;
  std::thread([&] { elsewhere = store.sun_state(model, sun); }).join();
  EXPECT_NE(elsewhere, first);
  EXPECT_EQ(states_made() - before, 2);
  // Another sun is prepared.
  EXPECT_EQ(store.sun_state(model, SunPosition{0.71, 0.25})->sun().zenith_rad, 0.71);
  EXPECT_EQ(states_made() - before, 3);
}

}  // namespace
}  // namespace clearsky::server
