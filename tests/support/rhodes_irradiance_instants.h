// Three instants of 2013-05-27 at Rhodes Hall, Cornell (42.443449 N, 76.481962 W, 250 m, EDT):
// 09:30 and 12:00 with the sun up, and 02:00 at night. The broadband evaluation and fit tests fill
// their GHI, DHI and DNI from a model, so that the model's own error on them is zero.
#pragma once

#include <vector>

#include "storage/repositories/irradiance_sample_repository.h"

namespace clearsky::testing {

// A sample at Rhodes Hall at the given instant, its components unset.
inline storage::IrradianceSample rhodes_hall_sample(double time_utc_s) {
  storage::IrradianceSample s;
  s.time_utc_s = time_utc_s;
  s.utc_offset_minutes = -240;
  s.latitude_deg = 42.443449;
  s.longitude_deg = -76.481962;
  s.elevation_m = 250;
  return s;
}

inline std::vector<storage::IrradianceSample> rhodes_irradiance_instants() {
  std::vector<storage::IrradianceSample> samples;
  for (double t : {1369661400.0, 1369670400.0, 1369634400.0})
    samples.push_back(rhodes_hall_sample(t));
  return samples;
}

}  // namespace clearsky::testing
