// The broadband integrals over the sun zenith (broadband_zenith_table.h).
#include "api/irradiance/broadband_zenith_table.h"

#include <algorithm>
#include <cmath>

#include "models/core/numeric.h"

namespace clearsky::api {

BroadbandZenithTable::BroadbandZenithTable(const WavelengthGrid& grid,
                                           const std::vector<std::size_t>& indices,
                                           const BroadbandConditions& conditions) {
  nodes_.reserve(kNodes);
  BroadbandConditions node = conditions;
  for (std::size_t k = 0; k < kNodes; ++k) {
    // The last node, 90 degrees, is the horizon: no direct beam, as the per-sun integration.
    node.sun_zenith_rad = degrees_to_radians(static_cast<double>(k) * kNodeStepDeg);
    nodes_.push_back(broadband_integrals(grid, indices, node));
  }
}

BroadbandIntegrals BroadbandZenithTable::at(double zenith_rad) const {
  const double x = std::clamp(radians_to_degrees(zenith_rad) / kNodeStepDeg, 0.0,
                              static_cast<double>(kNodes - 1));
  const std::size_t k = std::min(static_cast<std::size_t>(x), kNodes - 2);
  const double t = x - static_cast<double>(k);
  const BroadbandIntegrals& a = nodes_[k];
  const BroadbandIntegrals& b = nodes_[k + 1];
  const auto lerp = [t](double u, double v) { return u + t * (v - u); };
  BroadbandIntegrals out;
  out.mean_absorption.resize(a.mean_absorption.size());
  for (std::size_t i = 0; i < a.mean_absorption.size(); ++i)
    out.mean_absorption[i] = lerp(a.mean_absorption[i], b.mean_absorption[i]);
  out.direct_below_w_m2 = lerp(a.direct_below_w_m2, b.direct_below_w_m2);
  out.direct_above_w_m2 = lerp(a.direct_above_w_m2, b.direct_above_w_m2);
  out.diffuse_below_w_m2 = lerp(a.diffuse_below_w_m2, b.diffuse_below_w_m2);
  out.diffuse_above_w_m2 = lerp(a.diffuse_above_w_m2, b.diffuse_above_w_m2);
  out.diffuse_first_w_m2_nm = lerp(a.diffuse_first_w_m2_nm, b.diffuse_first_w_m2_nm);
  out.diffuse_last_w_m2_nm = lerp(a.diffuse_last_w_m2_nm, b.diffuse_last_w_m2_nm);
  return out;
}

}  // namespace clearsky::api
