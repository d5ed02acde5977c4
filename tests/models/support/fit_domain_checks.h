// The contract of fitted models outside their domain (models/core/fit_domain.h), shared by
// the Preetham and Hosek tests: with the sun at a given zenith, views where the fit turns
// negative are refused (outside_fit_domain, no number) by the default model, answered by the
// clamped one (clamp_negative_fit=1) with 0 at some wavelength, and equal elsewhere; refusals
// occur only near the horizon; the sky irradiance is the same with both.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "models/core/numeric.h"
#include "models/core/sky_model.h"

namespace clearsky::testing {

// The views of the check: 2.5 x 10 degree steps over the upper hemisphere.
inline std::vector<ViewDirection> fit_domain_views() {
  std::vector<ViewDirection> views;
  for (double z = 0.0; z <= 90.0; z += 2.5)
    for (double a = 0.0; a < 360.0; a += 10.0)
      views.push_back({degrees_to_radians(z), degrees_to_radians(a)});
  return views;
}

// Checks the contract for the sun at sun_zenith_deg (azimuth 0); returns the refused views.
inline int expect_refused_only_where_the_fit_turns_negative(const SkyModel& model,
                                                            const SkyModel& clamped,
                                                            double sun_zenith_deg) {
  const std::vector<ViewDirection> views = fit_domain_views();
  const auto sun = model.prepare_sun({degrees_to_radians(sun_zenith_deg), 0.0});
  SpectralBatch refused, answered;
  model.sky_radiance(*sun, {}, views, refused);
  clamped.sky_radiance(*sun, {}, views, answered);
  int outside = 0;
  for (std::size_t i = 0; i < views.size(); ++i) {
    EXPECT_EQ(answered.status[i], SampleStatus::ok) << sun_zenith_deg << " view " << i;
    const auto l = answered.spectrum(i);
    for (double v : l) EXPECT_TRUE(std::isfinite(v) && v >= 0.0);
    if (refused.status[i] == SampleStatus::ok) {
      const auto r = refused.spectrum(i);
      for (std::size_t w = 0; w < l.size(); ++w) EXPECT_EQ(r[w], l[w]);
      continue;
    }
    EXPECT_EQ(refused.status[i], SampleStatus::outside_fit_domain)
        << sun_zenith_deg << " view " << i;
    ++outside;
    // Refused samples carry no number; the clamped answer has a wavelength of no light.
    for (double v : refused.spectrum(i)) EXPECT_EQ(v, 0.0);
    EXPECT_EQ(*std::min_element(l.begin(), l.end()), 0.0);
    // Only near the horizon.
    EXPECT_GT(views[i].zenith_rad, degrees_to_radians(60.0));
  }
  const SpectralSample e = model.sky_irradiance(*sun, {});
  const SpectralSample e_clamped = clamped.sky_irradiance(*sun, {});
  EXPECT_EQ(e.status, SampleStatus::ok);
  for (std::size_t w = 0; w < e.value.size(); ++w) EXPECT_EQ(e.value[w], e_clamped.value[w]);
  return outside;
}

}  // namespace clearsky::testing
