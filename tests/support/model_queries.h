// Small query helpers shared by the model tests: one view's radiance, a sun position in
// degrees, and the sky irradiance on horizontal and tilted planes by independent fine rules
// (Gauss-Legendre in cos(theta) x midpoint in azimuth) to check a model's own quadrature.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "models/core/quadrature.h"
#include "models/core/sky_model.h"

namespace clearsky::testing {

inline SunPosition sun_at(double zenith_deg, double azimuth_deg = 135.0) {
  return {degrees_to_radians(zenith_deg), degrees_to_radians(azimuth_deg)};
}

// The radiance of one view (degrees); a non-ok status is a test failure.
inline Spectrum radiance(const SkyModel& model, const SunState& sun, double zenith_deg,
                         double azimuth_deg) {
  const std::vector<ViewDirection> views = {
      {degrees_to_radians(zenith_deg), degrees_to_radians(azimuth_deg)}};
  SpectralBatch batch;
  model.sky_radiance(sun, {}, views, batch);
  EXPECT_EQ(batch.status[0], SampleStatus::ok);
  return Spectrum(std::vector<double>(batch.spectrum(0).begin(), batch.spectrum(0).end()));
}

inline Spectrum reference_sky_irradiance(const SkyModel& model, const SunState& sun,
                                         int zenith_nodes, int azimuth_nodes) {
  std::vector<ViewDirection> views;
  std::vector<double> weights;
  for (const auto& [mu, w] : gauss_legendre(zenith_nodes, 0.0, 1.0)) {
    for (int j = 0; j < azimuth_nodes; ++j) {
      views.push_back({std::acos(mu), 2.0 * kPi * (j + 0.5) / azimuth_nodes});
      weights.push_back(w * mu * 2.0 * kPi / azimuth_nodes);
    }
  }
  SpectralBatch batch;
  model.sky_radiance(sun, {}, views, batch);
  Spectrum sum(model.wavelengths().size(), 0.0);
  for (std::size_t i = 0; i < views.size(); ++i) {
    EXPECT_EQ(batch.status[i], SampleStatus::ok);
    for (std::size_t w = 0; w < sum.size(); ++w) sum[w] += weights[i] * batch.spectrum(i)[w];
  }
  return sum;
}

// Sky irradiance on a tilted plane by an independent fine rule: 120 x 240 directions over the
// sky (Gauss-Legendre in cos(theta) x midpoint in azimuth), weight max(0, d . n).
inline Spectrum reference_tilted_irradiance(const SkyModel& model, const SunState& sun,
                                            const PlaneOrientation& plane) {
  const Vec3 n = SkyDirection{plane.tilt_rad, plane.azimuth_rad}.unit_vector();
  std::vector<ViewDirection> views;
  std::vector<double> weights;
  for (const auto& [mu, w] : gauss_legendre(120, 0.0, 1.0)) {
    for (int j = 0; j < 240; ++j) {
      const ViewDirection v{std::acos(mu), 2.0 * kPi * (j + 0.5) / 240};
      const double c = dot(v.unit_vector(), n);
      if (c <= 0.0) continue;
      views.push_back(v);
      weights.push_back(w * c * 2.0 * kPi / 240);
    }
  }
  SpectralBatch batch;
  model.sky_radiance(sun, {}, views, batch);
  Spectrum sum(model.wavelengths().size(), 0.0);
  for (std::size_t i = 0; i < views.size(); ++i) {
    for (std::size_t w = 0; w < sum.size(); ++w) sum[w] += weights[i] * batch.spectrum(i)[w];
  }
  return sum;
}

}  // namespace clearsky::testing
