// The tabulated sky irradiance of a tilted plane (plane_sky_irradiance_table.h).
#include "api/irradiance/plane_sky_irradiance_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "models/core/numeric.h"
#include "models/core/parallel.h"

namespace clearsky::api {

PlaneSkyIrradianceTable::PlaneSkyIrradianceTable(const SkyModel& model, const Viewpoint& viewpoint,
                                                 const PlaneOrientation& plane)
    : plane_(plane), nodes_(kNodes) {
  if (model.descriptor().capabilities.per_sun_precomputation)
    throw std::logic_error("a sky irradiance table for a model that prepares each sun");
  // Each node its own slot: the two workers write disjoint elements.
  parallel_for(
      kNodes,
      [&](std::size_t k) {
        const int i = static_cast<int>(k) / kAzimuthNodes, j = static_cast<int>(k) % kAzimuthNodes;
        const SunPosition sun{degrees_to_radians(i * kZenithStepDeg),
                              plane.azimuth_rad + degrees_to_radians(j * kAzimuthStepDeg)};
        if (model.check_sun(sun) != SampleStatus::ok) return;
        const auto state = model.prepare_sun(sun);
        SpectralSample e = model.sky_irradiance(*state, viewpoint, plane);
        if (e.status == SampleStatus::ok) nodes_[k] = std::move(e.value);
      },
      kWorkers);
}

const Spectrum* PlaneSkyIrradianceTable::node(int zenith, int azimuth) const {
  const auto& n = nodes_[static_cast<std::size_t>(zenith * kAzimuthNodes + azimuth)];
  return n ? &*n : nullptr;
}

std::optional<Spectrum> PlaneSkyIrradianceTable::at(const SunPosition& sun) const {
  const double zenith_deg = radians_to_degrees(sun.zenith_rad);
  if (!(zenith_deg >= 0.0 && zenith_deg <= 90.0)) return std::nullopt;
  // |delta phi| folded into [0, 180] degrees.
  double delta_deg =
      std::fmod(std::abs(radians_to_degrees(sun.azimuth_rad - plane_.azimuth_rad)), 360.0);
  if (delta_deg > 180.0) delta_deg = 360.0 - delta_deg;
  const double x = zenith_deg / kZenithStepDeg, y = delta_deg / kAzimuthStepDeg;
  const int i = std::min(static_cast<int>(x), kZenithNodes - 2);
  const int j = std::min(static_cast<int>(y), kAzimuthNodes - 2);
  const double u = x - i, v = y - j;
  const Spectrum* e00 = node(i, j);
  const Spectrum* e01 = node(i, j + 1);
  const Spectrum* e10 = node(i + 1, j);
  const Spectrum* e11 = node(i + 1, j + 1);
  if (!e00 || !e01 || !e10 || !e11) return std::nullopt;
  Spectrum out(e00->size(), 0.0);
  for (std::size_t w = 0; w < out.size(); ++w) {
    out[w] =
        (1 - u) * ((1 - v) * (*e00)[w] + v * (*e01)[w]) + u * ((1 - v) * (*e10)[w] + v * (*e11)[w]);
  }
  return out;
}

}  // namespace clearsky::api
