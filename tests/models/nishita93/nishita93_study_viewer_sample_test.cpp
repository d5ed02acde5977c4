// Nishita93's option study_viewer_sample (models/nishita93/README.md): the study's zero
// integrand at the observer, which drops half of the first layer's light, at every view. It
// was once silently ignored at about 14 % of view zeniths (60, 70, 80, 85 and 89 degrees among
// them): the crossing of the observer's own sphere, computed with rounding, landed a few 1e-10 m
// beyond the observer and became a second sample carrying the true integrand.
#include <gtest/gtest.h>

#include <vector>

#include "models/nishita93/nishita93.h"
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

}  // namespace
}  // namespace clearsky
