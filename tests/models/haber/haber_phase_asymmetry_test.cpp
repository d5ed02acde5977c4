// Haber's declared limit on the Cornette-Shanks asymmetry (models/haber/haber.h): at g = -0.999
// sky + direct irradiance reached 1.64 times the extraterrestrial irradiance (285.875 nm, sun
// zenith 30; found by `clearsky stress`, docs/stability.md). |g| above 0.9 is refused naming g;
// at the limits the energy bound holds.
#include <gtest/gtest.h>

#include <cmath>

#include "models/core/invalid_input.h"
#include "models/core/numeric.h"
#include "models/haber/haber.h"

namespace clearsky {
namespace {

ModelConfig config_with_g(double g) {
  ModelConfig config;
  config.wavelengths = WavelengthGrid::points({285.875, 550.0});
  config.atmosphere.mie_phase_g = g;
  config.options["azimuth_sectors"] = 24;
  return config;
}

TEST(HaberPhaseAsymmetry, DescriptorDeclaresTheLimitAndTheFactoryRefusesBeyondIt) {
  const ParameterSpec* g = haber::model_descriptor().find_parameter("g");
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->min_value, -haber::kMaxPhaseAsymmetry);
  EXPECT_EQ(g->max_value, haber::kMaxPhaseAsymmetry);
  try {
    haber::model_factory().create(config_with_g(-0.999), {});
    ADD_FAILURE() << "g = -0.999 accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "g");
  }
}

TEST(HaberPhaseAsymmetry, SkyAndSunStayBelowTheExtraterrestrialIrradianceAtTheLimits) {
  for (double g : {-haber::kMaxPhaseAsymmetry, haber::kMaxPhaseAsymmetry}) {
    const auto model = haber::model_factory().create(config_with_g(g), {});
    const double sun_zenith_rad = degrees_to_radians(30.0);
    const auto sun = model->prepare_sun({sun_zenith_rad, degrees_to_radians(180.0)});
    const SpectralSample direct = model->sun_irradiance(*sun, {0.0});
    const SpectralSample sky = model->sky_irradiance(*sun, {0.0});
    ASSERT_EQ(sky.status, SampleStatus::ok);
    for (std::size_t w = 0; w < 2; ++w) {
      const double top = model->atmosphere().solar_irradiance_w_m2_nm[w] * std::cos(sun_zenith_rad);
      EXPECT_LT(sky.value[w] + direct.value[w] * std::cos(sun_zenith_rad), top)
          << "g " << g << " wavelength " << model->wavelengths()[w];
    }
  }
}

}  // namespace
}  // namespace clearsky
