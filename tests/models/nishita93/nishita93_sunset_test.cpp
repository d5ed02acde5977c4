// Nishita93 at sunset (models/nishita93/README.md "The sun at the horizon"): the radiance is
// continuous in the sun zenith through 90 degrees. It once fell by 99.6 % at the zenith
// between 90.0 and 90.1 degrees (and 52 % in 0.1 degree for a view 60 degrees from the zenith,
// away from the sun, before 90), where the sun-side optical length switched from the
// along-axis table to the against-axis one, whose cells next to the horizon hold rays grazing
// the ground; single-scattering O'Neal and the reference integrator change by a few percent.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "models/core/single_scattering_reference.h"
#include "models/nishita93/nishita93.h"
#include "tests/models/support/sky_properties.h"

namespace clearsky {
namespace {

using testing::radiance_of;
using testing::sun_at_degrees;
using testing::view_at_degrees;

const Nishita93Model& paper_model_at_440nm() {
  static const auto model = [] {
    ModelConfig config;
    config.wavelengths = WavelengthGrid::points({440.0});
    return Nishita93Model::create(config);
  }();
  return *model;
}

double radiance_at(double sun_zenith_deg, const ViewDirection& view) {
  const SpectralBatch out =
      radiance_of(paper_model_at_440nm(), sun_at_degrees(sun_zenith_deg), 0.0, {view});
  EXPECT_EQ(out.status[0], SampleStatus::ok);
  return out.spectrum(0)[0];
}

// From 85 to 100 degrees in 0.01-degree steps, at the zenith and 60 and 85 degrees from it
// towards and away from the sun: the radiance never rises, and while the sky is lit (above
// 1e-3 of its value at 85 degrees) no step takes more than 6 %; it then fades to the black of
// the Earth's shadow (the whole 60 km atmosphere above the observer is in it beyond 97.8
// degrees).
TEST(Nishita93Sunset, RadianceDecreasesSmoothlyThroughTheHorizon) {
  for (const ViewDirection& view : {view_at_degrees(0.0, 0.0), view_at_degrees(60.0, 180.0),
                                    view_at_degrees(60.0, 0.0), view_at_degrees(85.0, 180.0)}) {
    const double start = radiance_at(85.0, view);
    ASSERT_GT(start, 0.0);
    double previous = start;
    double largest_drop = 0.0;
    for (int step = 1; step <= 1500; ++step) {
      const double sun_zenith = 85.0 + 0.01 * step;
      const double value = radiance_at(sun_zenith, view);
      ASSERT_TRUE(std::isfinite(value) && value >= 0.0) << sun_zenith;
      EXPECT_LE(value, previous * (1.0 + 1e-9)) << view.zenith_rad << ' ' << sun_zenith;
      if (previous > 1e-3 * start) largest_drop = std::max(largest_drop, 1.0 - value / previous);
      previous = value;
    }
    EXPECT_LT(largest_drop, 0.06) << view.zenith_rad;
    EXPECT_EQ(previous, 0.0) << view.zenith_rad;  // the sun 10 degrees below the horizon
  }
}

// Across the horizon the model follows the double-precision reference within its known
// near-horizon error (README: about 35 % too dark at 85 degrees), not by orders of magnitude.
TEST(Nishita93Sunset, FollowsTheReferenceThroughTwilight) {
  const Nishita93Model& model = paper_model_at_440nm();
  for (double sun_zenith : {89.9, 90.0, 90.1, 91.0, 92.0, 93.0, 94.0}) {
    const ViewDirection view = view_at_degrees(0.0, 0.0);
    const auto reference = single_scattering_reference(
        model.atmosphere(), RaySunGeometry::from(model.config().atmosphere.earth_radius_m, {0.0},
                                                 view, sun_at_degrees(sun_zenith)));
    const double ratio = radiance_at(sun_zenith, view) / reference.radiance[0];
    EXPECT_GT(ratio, 0.6) << sun_zenith;
    EXPECT_LT(ratio, 1.5) << sun_zenith;
  }
}

}  // namespace
}  // namespace clearsky
