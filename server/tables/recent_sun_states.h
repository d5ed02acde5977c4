// The last few per-sun states one server thread prepared, for the models whose state is made
// anew for each request (those without per-sun precomputation; Haber and Nishita96 keep their
// own bounded, single-flight caches: models/core/sun_state_cache.h). Clients ask for one sky
// many times over: a renderer or a daylighting tool's sensor grid sends one request per view,
// the same sun in each. Hosek's state (its fitted distributions cooked for the sun's elevation,
// the turbidity and the albedo: models/hosek/README.md) is about 85,000 instructions, more than
// the rest of its radiance answer; kept per thread, a repeated sun finds it without a lock.
//
// A state is found for the same model object (held by a weak pointer: a model freed and another
// made at its address never matches) and the same sun, bit for bit; states are immutable, so
// the answer is the one prepare_sun() would make. Small states only (kMaxStateBytes; Hosek's is
// about 7 kB): a thread keeps at most kSlots x kMaxStateBytes, 64 KiB, so the server's 512
// workers at most 32 MiB (docs/tables-and-memory.md).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "models/core/sky_model.h"

namespace clearsky::server {

class RecentSunStates {
 public:
  static constexpr std::size_t kSlots = 4;
  static constexpr std::size_t kMaxStateBytes = 16 * 1024;

  // The state kept for model and sun; null when none is.
  std::shared_ptr<const SunState> find(const std::shared_ptr<const SkyModel>& model,
                                       const SunPosition& sun) const;
  // Keeps state (made by model for sun) in place of the slot used longest ago; a state above
  // kMaxStateBytes is not kept.
  void keep(const std::shared_ptr<const SkyModel>& model, const SunPosition& sun,
            std::shared_ptr<const SunState> state);

  // This thread's instance.
  static RecentSunStates& of_this_thread();

 private:
  struct Slot {
    std::weak_ptr<const SkyModel> model;
    const SkyModel* model_address = nullptr;
    std::uint64_t zenith_bits = 0;
    std::uint64_t azimuth_bits = 0;
    std::shared_ptr<const SunState> state;
  };
  std::array<Slot, kSlots> slots_{};
  std::size_t next_ = 0;  // the slot the next keep() replaces (round robin)
};

}  // namespace clearsky::server
