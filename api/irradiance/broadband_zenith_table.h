// The broadband integrals (broadband_irradiance.h) of a long time series tabulated over the sun
// zenith: for one request the atmosphere, the altitude and the grid are fixed, so the
// integrals depend on the sun's zenith (its air mass) alone, and a year of hourly steps needs
// them at about 4,400 zeniths where 181 nodes (0 to 90 degrees every 0.5) interpolated
// linearly do: the per-sun integration (about 1 ms of SPCTRAL2 per sun,
// tests/bench/broadband_irradiance_bench.cpp) is then done 181 times, not once per step. GET
// /v1/irradiance/series uses it when the series has more daytime steps than the table has
// nodes (its answer says which: broadband.integration). Interpolation error:
// BroadbandZenithTable.InterpolatesTheExactIntegrals (tests/api/irradiance). Immutable after
// construction; thread-safe.
#pragma once

#include <cstddef>
#include <vector>

#include "api/irradiance/broadband_irradiance.h"

namespace clearsky::api {

class BroadbandZenithTable {
 public:
  static constexpr std::size_t kNodes = 181;
  static constexpr double kNodeStepDeg = 0.5;

  // conditions: the request's (its sun zenith is not used).
  BroadbandZenithTable(const WavelengthGrid& grid, const std::vector<std::size_t>& indices,
                       const BroadbandConditions& conditions);

  // The integrals at a sun zenith in [0, pi/2], linear between the two nearest nodes.
  BroadbandIntegrals at(double zenith_rad) const;

 private:
  std::vector<BroadbandIntegrals> nodes_;
};

}  // namespace clearsky::api
