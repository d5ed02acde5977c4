// The Lambertian ground of Nishita93 and O'Neal (models/core/lambertian_ground.h): a view that
// meets the ground sees the shared albedo lit by the sun and the model's own sky, through the
// air before it. They once answered about 6e-12 W/(m2.sr.nm) there: a black ground, silently.
#include "models/core/lambertian_ground.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "models/registry.h"
#include "tests/models/support/sky_properties.h"

namespace clearsky {
namespace {

using testing::radiance_of;
using testing::sun_at_degrees;
using testing::view_at_degrees;

std::shared_ptr<const SkyModel> model_of(const std::string& id, double albedo = -1.0) {
  ModelConfig config;
  config.wavelengths = WavelengthGrid::points({440.0, 550.0, 680.0});
  if (albedo >= 0.0) config.atmosphere.ground_albedo = albedo;
  return find_model(id)->create(config, {});
}

class LambertianGroundOf : public ::testing::TestWithParam<std::string> {};

// From the ground, every view below the horizon sees the ground at the observer's feet:
// albedo / pi (direct sun on the horizontal + the model's own sky irradiance).
TEST_P(LambertianGroundOf, GroundAtTheObserverIsTheLitGrass) {
  const auto model = model_of(GetParam());
  for (double sun_zenith : {30.0, 60.0, 85.0}) {
    const auto state = model->prepare_sun(sun_at_degrees(sun_zenith));
    const SpectralSample sun = model->sun_irradiance(*state, {0.0});
    const SpectralSample sky = model->sky_irradiance(*state, {0.0});
    ASSERT_EQ(sun.status, SampleStatus::ok);
    ASSERT_EQ(sky.status, SampleStatus::ok);
    const double mu_s = std::cos(sun_zenith * kDegree);
    const SpectralBatch out = radiance_of(
        *model, sun_at_degrees(sun_zenith), 0.0,
        {view_at_degrees(90.1, 0.0), view_at_degrees(120.0, 90.0), view_at_degrees(180.0, 0.0)});
    for (std::size_t v = 0; v < out.size(); ++v) {
      ASSERT_EQ(out.status[v], SampleStatus::ok);
      for (std::size_t w = 0; w < 3; ++w) {
        const double expected =
            model->atmosphere().ground_albedo[w] / kPi * (sun.value[w] * mu_s + sky.value[w]);
        // The sky irradiance is tabulated every 0.025 in mu_s: within 1 %, 5 % for a low sun
        // (where it bends most).
        EXPECT_NEAR(out.spectrum(v)[w] / expected, 1.0, sun_zenith < 80.0 ? 0.01 : 0.05)
            << GetParam() << " sun " << sun_zenith << " view " << v << " wavelength " << w;
        EXPECT_GT(out.spectrum(v)[w], sun_zenith < 80.0 ? 1e-3 : 1e-4) << GetParam();
      }
    }
  }
}

// From 10 km, a view 30 degrees below the horizontal: the air's light plus the ground's
// through the air's transmittance; a black ground (albedo 0) leaves the air's light only.
TEST_P(LambertianGroundOf, GroundFromAboveIsSeenThroughTheAir) {
  const auto model = model_of(GetParam());
  const auto black = model_of(GetParam(), 0.0);
  const ViewDirection view = view_at_degrees(120.0, 45.0);
  const auto state = model->prepare_sun(sun_at_degrees(40.0));
  const AerialPerspectiveSample air =
      model->aerial_perspective(*state, {10e3}, view, std::numeric_limits<double>::infinity());
  ASSERT_EQ(air.status, SampleStatus::ok);
  const SpectralBatch out = radiance_of(*model, sun_at_degrees(40.0), 10e3, {view});
  const SpectralBatch dark = radiance_of(*black, sun_at_degrees(40.0), 10e3, {view});
  // The ground point is ~20 km away: its sun is the observer's within 0.2 degree.
  const SpectralSample sun = model->sun_irradiance(*state, {0.0});
  const SpectralSample sky = model->sky_irradiance(*state, {0.0});
  for (std::size_t w = 0; w < 3; ++w) {
    EXPECT_EQ(dark.spectrum(0)[w], air.radiance[w]) << GetParam();
    const double ground = model->atmosphere().ground_albedo[w] / kPi *
                          (sun.value[w] * std::cos(40.0 * kDegree) + sky.value[w]);
    EXPECT_NEAR((out.spectrum(0)[w] - air.radiance[w]) / (air.transmittance[w] * ground), 1.0, 0.02)
        << GetParam() << ' ' << w;
  }
}

INSTANTIATE_TEST_SUITE_P(SingleScattering, LambertianGroundOf,
                         ::testing::Values("nishita93", "oneal"));

}  // namespace
}  // namespace clearsky
