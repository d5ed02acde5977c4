// Arrangement of measured samples on the concentric rings (concentric_sky_interpolant.h).
#include "models/evaluation/concentric_sky_interpolant.h"

#include <string>

namespace clearsky {

std::array<std::vector<std::size_t>, kConcentricRingCount> arrange_concentric_rings(
    std::span<const MeasuredSample> samples) {
  constexpr double kTolerance = 0.01 * kPi / 180.0;
  constexpr std::size_t kUnset = static_cast<std::size_t>(-1);
  std::array<std::vector<std::size_t>, kConcentricRingCount> rings;
  for (int k = 0; k < kConcentricRingCount; ++k) rings[k].assign(concentric_ring_size(k), kUnset);
  for (std::size_t s = 0; s < samples.size(); ++s) {
    const ViewDirection& view = samples[s].view;
    bool placed = false;
    for (int k = 0; k < kConcentricRingCount && !placed; ++k) {
      if (std::abs(view.zenith_rad - concentric_ring_zenith_rad(k)) > kTolerance) continue;
      const double n = static_cast<double>(concentric_ring_size(k));
      const double step = 2.0 * kPi / n;
      double slot = k == 0 ? 0.0 : std::round(view.azimuth_rad / step);
      if (k > 0 && std::abs(view.azimuth_rad - slot * step) > kTolerance) break;
      slot = std::fmod(std::fmod(slot, n) + n, n);
      auto& cell = rings[k][static_cast<std::size_t>(slot)];
      if (cell != kUnset)
        throw std::invalid_argument("samples " + std::to_string(samples[cell].index) + " and " +
                                    std::to_string(samples[s].index) + " share a direction");
      cell = s;
      placed = true;
    }
    if (!placed)
      throw std::invalid_argument("sample " + std::to_string(samples[s].index) +
                                  " is not a direction of the 81-sample concentric layout");
  }
  for (int k = 0; k < kConcentricRingCount; ++k) {
    for (std::size_t m = 0; m < rings[k].size(); ++m) {
      if (rings[k][m] == kUnset)
        throw std::invalid_argument(
            "no sample on ring " + std::to_string(k) + " at azimuth " +
            std::to_string(360.0 * static_cast<double>(m) / static_cast<double>(rings[k].size())) +
            " deg");
    }
  }
  return rings;
}

bool is_concentric_layout(std::span<const MeasuredSample> samples) {
  try {
    arrange_concentric_rings(samples);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

}  // namespace clearsky
