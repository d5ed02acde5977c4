// Nishita93's option study_viewer_sample (models/nishita93/README.md): the study's zero
// integrand at the observer, which drops half of the first layer's light, at every view. It
// was once silently ignored at about 14 % of view zeniths (60, 70, 80, 85 and 89 degrees among
// them): the crossing of the observer's own sphere, computed with rounding, landed a few 1e-10 m
// beyond the observer and became a second sample carrying the true integrand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "models/nishita93/nishita93.h"
#include "models/nishita93/nishita93_tables.h"
#include "models/stress/documented_jumps.h"
#include "tests/models/support/sky_properties.h"

namespace clearsky {
namespace {

using testing::radiance_of;
using testing::sun_at_degrees;
using testing::view_at_degrees;

std::shared_ptr<const Nishita93Model> model_at_440nm(bool study_viewer_sample) {
  ModelConfig config;
  config.wavelengths = WavelengthGrid::points({440.0});
  config.options["study_viewer_sample"] = study_viewer_sample ? 1.0 : 0.0;
  return Nishita93Model::create(config);
}

// Every view zenith from 0 to 89.95 degrees in 0.05-degree steps, in and across the sun's
// vertical plane: the option always darkens the sky (by 1 % or more here: half the light of the
// first layer, 128 m thick, along the view), never leaves it as it is.
TEST(Nishita93StudyViewerSample, DarkensEveryView) {
  const auto plain = model_at_440nm(false);
  const auto study = model_at_440nm(true);
  std::vector<ViewDirection> views;
  for (int i = 0; i < 1800; ++i)
    for (double azimuth : {0.0, 90.0, 180.0}) views.push_back(view_at_degrees(0.05 * i, azimuth));
  for (double sun_zenith : {30.0, 60.0}) {
    const SpectralBatch a = radiance_of(*plain, sun_at_degrees(sun_zenith), 0.0, views);
    const SpectralBatch b = radiance_of(*study, sun_at_degrees(sun_zenith), 0.0, views);
    int ignored = 0;
    for (std::size_t v = 0; v < views.size(); ++v) {
      ASSERT_EQ(a.status[v], SampleStatus::ok);
      ASSERT_EQ(b.status[v], SampleStatus::ok);
      if (!(b.spectrum(v)[0] < 0.999 * a.spectrum(v)[0])) ++ignored;
      // Half the first layer's light: at most half the sky except near the horizon, where the
      // first sphere crossing is tens of kilometres away.
      if (views[v].zenith_rad < degrees_to_radians(85.0)) {
        EXPECT_GT(b.spectrum(v)[0], 0.5 * a.spectrum(v)[0]) << v;
      }
    }
    EXPECT_EQ(ignored, 0) << "sun " << sun_zenith;
  }
}

// The option's trapezoid weighs the segment from the observer to the first sphere crossing with
// the far end's integrand only. When the observer rises through a sphere, that segment grows
// from nearly nothing to the whole way to the next sphere, which is hundreds of kilometres for
// a near-horizontal view: the radiance jumps there by construction. The stress run names these
// altitudes as the documented jump study_viewer_sample_sphere (models/stress/documented_jumps.h)
// and only for models run with the option; without it the radiance is continuous.
TEST(Nishita93StudyViewerSample, JumpsAtTheSpheresWhereTheStressRunDocumentsIt) {
  const auto plain = model_at_440nm(false);
  const auto study = model_at_440nm(true);
  const AtmosphereParameters& atmosphere = study->config().atmosphere;
  const std::vector<double> radii_m = Nishita93Tables::sphere_radii_m(atmosphere, 64);
  // The first sphere above 30 km.
  const auto above = std::find_if(radii_m.begin(), radii_m.end(),
                                  [&](double r) { return r - atmosphere.earth_radius_m > 30e3; });
  ASSERT_NE(above, radii_m.end());
  const double sphere_altitude_m = *above - atmosphere.earth_radius_m;
  const std::vector<ViewDirection> views = {view_at_degrees(89.5, 0.0)};
  const auto radiance_at = [&](const Nishita93Model& m, double altitude_m) {
    const SpectralBatch b = radiance_of(m, sun_at_degrees(30.0), altitude_m, views);
    EXPECT_EQ(b.status[0], SampleStatus::ok);
    return b.spectrum(0)[0];
  };
  const double below_m = sphere_altitude_m - 50.0, above_m = sphere_altitude_m + 50.0;
  const double study_below = radiance_at(*study, below_m),
               study_above = radiance_at(*study, above_m);
  const double plain_below = radiance_at(*plain, below_m),
               plain_above = radiance_at(*plain, above_m);
  const auto relative_change = [](double a, double b) {
    return std::abs(a - b) / std::max(std::abs(a), std::abs(b));
  };
  EXPECT_GT(relative_change(study_below, study_above), 0.5)
      << study_below << " -> " << study_above << " at " << sphere_altitude_m << " m";
  EXPECT_LT(relative_change(plain_below, plain_above), 0.05)
      << plain_below << " -> " << plain_above << " at " << sphere_altitude_m << " m";

  const auto documented = stress::documented_altitude_jumps(*study, 89.5, "view");
  EXPECT_TRUE(std::any_of(documented.begin(), documented.end(), [&](const auto& j) {
    return j.name == "study_viewer_sample_sphere" && j.coordinate > below_m &&
           j.coordinate < above_m && j.chain == "view";
  }));
  for (const auto& j : stress::documented_altitude_jumps(*plain, 89.5, "view"))
    EXPECT_NE(j.name, "study_viewer_sample_sphere");
}

}  // namespace
}  // namespace clearsky
