// Synthetic captures on the 81-direction layout of Kider et al. 2014 for tests of the
// evaluation: every sample's spectrum is given by a function of its direction and wavelength,
// tabulated every 1 nm from 350 to 900 nm.
#pragma once

#include <functional>

#include "models/core/numeric.h"
#include "models/evaluation/concentric_sky_interpolant.h"
#include "models/evaluation/measured_sky.h"

namespace clearsky::testing {

using SkyFunction = std::function<double(const ViewDirection& view, double wavelength_nm)>;

inline MeasuredCapture synthetic_capture(const SkyFunction& radiance, double sun_zenith_deg = 40.0,
                                         double sun_azimuth_deg = 120.0) {
  MeasuredCapture capture;
  capture.label = "synthetic";
  capture.unix_time_utc_s = 1369661400.0;  // 2013-05-27T13:30:00Z
  capture.utc_offset_minutes = -240;
  capture.site = kider_cornell_site();
  std::vector<double> nm;
  for (int w = 350; w <= 900; ++w) nm.push_back(w);
  int index = 0;
  for (int ring = 0; ring < kConcentricRingCount; ++ring) {
    const std::size_t n = concentric_ring_size(ring);
    for (std::size_t m = 0; m < n; ++m) {
      MeasuredSample sample;
      sample.index = index++;
      sample.view = {concentric_ring_zenith_rad(ring), 2.0 * kPi * static_cast<double>(m) / static_cast<double>(n)};
      std::vector<double> values;
      for (double w : nm) values.push_back(radiance(sample.view, w));
      sample.radiance = TabulatedSpectrum(nm, std::move(values));
      capture.samples.push_back(std::move(sample));
    }
  }
  capture.sun_zenith_computed_deg = sun_zenith_deg;
  capture.sun_azimuth_computed_deg = sun_azimuth_deg;
  capture.sun_azimuth_estimated_deg = sun_azimuth_deg;
  return capture;
}

}  // namespace clearsky::testing
