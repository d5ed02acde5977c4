// Physical properties every model answering all viewpoints must have (used by the tests of
// Nishita93, O'Neal and the other numerical models): finite non-negative radiance everywhere,
// continuity across the horizon, mirror symmetry about the sun's vertical plane.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "models/core/numeric.h"
#include "models/core/sky_model.h"

namespace clearsky::testing {

inline SunPosition sun_at_degrees(double zenith_deg, double azimuth_deg = 0.0) {
  return {degrees_to_radians(zenith_deg), degrees_to_radians(azimuth_deg)};
}
inline ViewDirection view_at_degrees(double zenith_deg, double azimuth_deg) {
  return {degrees_to_radians(zenith_deg), degrees_to_radians(azimuth_deg)};
}

inline SpectralBatch radiance_of(const SkyModel& model, const SunPosition& sun, double altitude_m,
                                 const std::vector<ViewDirection>& views) {
  SpectralBatch out;
  model.sky_radiance(*model.prepare_sun(sun), Viewpoint{altitude_m}, views, out);
  return out;
}

// Every sample ok, finite and >= 0 (the checked query turns a NaN or negative value into
// numerical_failure, so the status says it all), over altitudes from the ground to
// geostationary orbit, the sun from the zenith to the nadir, and views in every direction,
// the horizon included.
inline void expect_finite_non_negative_everywhere(const SkyModel& model) {
  std::vector<ViewDirection> views;
  for (double zenith = 0.0; zenith <= 180.0; zenith += 7.5) {
    for (double azimuth = 0.0; azimuth < 360.0; azimuth += 45.0)
      views.push_back(view_at_degrees(zenith, azimuth));
  }
  for (double zenith : {89.99, 90.0, 90.01}) views.push_back(view_at_degrees(zenith, 10.0));
  for (double altitude : {0.0, 1000.0, 59999.0, 60001.0, 1e6, 3.6e7}) {
    for (double sun_zenith : {0.0, 30.0, 89.0, 90.0, 91.0, 100.0, 150.0, 180.0}) {
      const SpectralBatch out =
          radiance_of(model, sun_at_degrees(sun_zenith, 30.0), altitude, views);
      for (std::size_t i = 0; i < views.size(); ++i) {
        ASSERT_EQ(out.status[i], SampleStatus::ok)
            << "altitude " << altitude << " sun " << sun_zenith << " view " << views[i].zenith_rad;
        for (double v : out.spectrum(i)) ASSERT_TRUE(is_finite_non_negative(v));
      }
    }
  }
}

// Largest relative difference over wavelengths between two spectra of a batch.
inline double relative_difference(const SpectralBatch& out, std::size_t a, std::size_t b) {
  double worst = 0.0;
  for (std::size_t w = 0; w < out.wavelength_count; ++w) {
    const double x = out.spectrum(a)[w], y = out.spectrum(b)[w];
    if (x == 0.0 && y == 0.0) continue;
    worst = std::max(worst, std::abs(x - y) / std::max(std::abs(x), std::abs(y)));
  }
  return worst;
}

// Views mirrored about the sun's vertical plane give the same radiance (to rounding).
inline void expect_symmetric_about_the_sun_plane(const SkyModel& model, double altitude_m) {
  const double sun_azimuth = 123.0;
  std::vector<ViewDirection> views;
  for (double zenith : {5.0, 45.0, 85.0, 95.0, 150.0}) {
    for (double offset : {10.0, 70.0, 135.0}) {
      views.push_back(view_at_degrees(zenith, sun_azimuth + offset));
      views.push_back(view_at_degrees(zenith, sun_azimuth - offset));
    }
  }
  const SpectralBatch out =
      radiance_of(model, sun_at_degrees(50.0, sun_azimuth), altitude_m, views);
  for (std::size_t i = 0; i < views.size(); i += 2)
    EXPECT_LT(relative_difference(out, i, i + 1), 1e-9) << i;
}

// Radiance is continuous across the astronomical horizon (view zenith 90 degrees) for an
// observer above the ground, and continuous from above at the horizon for one on the ground.
inline void expect_continuous_across_the_horizon(const SkyModel& model, double tolerance) {
  for (double azimuth : {0.0, 90.0, 180.0}) {
    const std::vector<ViewDirection> views = {view_at_degrees(90.0 - 1e-4, azimuth),
                                              view_at_degrees(90.0, azimuth),
                                              view_at_degrees(90.0 + 1e-4, azimuth)};
    const SpectralBatch high = radiance_of(model, sun_at_degrees(60.0), 1000.0, views);
    EXPECT_LT(relative_difference(high, 0, 1), tolerance) << azimuth;
    EXPECT_LT(relative_difference(high, 1, 2), tolerance) << azimuth;
    const SpectralBatch ground = radiance_of(model, sun_at_degrees(60.0), 0.0, views);
    EXPECT_LT(relative_difference(ground, 0, 1), tolerance) << azimuth;
  }
}

}  // namespace clearsky::testing
