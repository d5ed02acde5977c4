#include "server/tables/recent_sun_states.h"

#include <bit>

namespace clearsky::server {

namespace {

// Bit patterns, so that -0 and +0 (whose sines differ in sign) are different suns.
std::uint64_t bits(double value) { return std::bit_cast<std::uint64_t>(value); }

}  // namespace

std::shared_ptr<const SunState> RecentSunStates::find(const std::shared_ptr<const SkyModel>& model,
                                                      const SunPosition& sun) const {
  const std::uint64_t zenith = bits(sun.zenith_rad);
  const std::uint64_t azimuth = bits(sun.azimuth_rad);
  for (const Slot& slot : slots_) {
    // The address alone could be a new model's at a freed one's place: the weak pointer tells
    // whether the model kept is still the one alive there.
    if (slot.state != nullptr && slot.model_address == model.get() && slot.zenith_bits == zenith &&
        slot.azimuth_bits == azimuth && !slot.model.expired())
      return slot.state;
  }
  return nullptr;
}

void RecentSunStates::keep(const std::shared_ptr<const SkyModel>& model, const SunPosition& sun,
                           std::shared_ptr<const SunState> state) {
  if (state == nullptr || state->memory_bytes() > kMaxStateBytes) return;
  Slot& slot = slots_[next_];
  next_ = (next_ + 1) % kSlots;
  slot = {model, model.get(), bits(sun.zenith_rad), bits(sun.azimuth_rad), std::move(state)};
}

RecentSunStates& RecentSunStates::of_this_thread() {
  thread_local RecentSunStates states;
  return states;
}

}  // namespace clearsky::server
