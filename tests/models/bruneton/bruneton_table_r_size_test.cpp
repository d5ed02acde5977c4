// Bruneton's declared limit on table_r_size (models/bruneton/bruneton.h): with 2 altitudes (the
// ground and the top) the ground-irradiance table made sky + direct irradiance 15 to 29% above
// the extraterrestrial irradiance (table_r_size = 2, sun zenith 30, 285.875 and 550 nm; found
// by `clearsky stress`, docs/stability.md). 2 is refused naming the option; at 3 the energy
// bound holds.
#include <gtest/gtest.h>

#include <cmath>

#include "models/bruneton/bruneton.h"
#include "models/core/invalid_input.h"
#include "models/core/numeric.h"

namespace clearsky {
namespace {

ModelConfig small_tables(double r_size) {
  ModelConfig config;
  config.wavelengths = WavelengthGrid::points({285.875, 550.0});
  config.options = {{"table_r_size", r_size},
                    {"table_mu_size", 32},
                    {"table_mu_s_size", 8},
                    {"table_nu_size", 4}};
  return config;
}

TEST(BrunetonTableRSize, TwoAltitudesAreRefusedNamingTheOption) {
  EXPECT_EQ(bruneton_descriptor().find_parameter("table_r_size")->min_value, 3.0);
  try {
    bruneton_factory().create(small_tables(2), {});
    ADD_FAILURE() << "table_r_size = 2 accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "table_r_size");
  }
}

TEST(BrunetonTableRSize, ThreeAltitudesKeepSkyAndSunBelowTheExtraterrestrialIrradiance) {
  const auto model = bruneton_factory().create(small_tables(3), {});
  for (double sun_zenith_deg : {0.0, 30.0, 60.0}) {
    const double cos_sun = std::cos(degrees_to_radians(sun_zenith_deg));
    const auto sun = model->prepare_sun({degrees_to_radians(sun_zenith_deg), 0.0});
    const SpectralSample direct = model->sun_irradiance(*sun, {0.0});
    const SpectralSample sky = model->sky_irradiance(*sun, {0.0});
    ASSERT_EQ(sky.status, SampleStatus::ok);
    for (std::size_t w = 0; w < 2; ++w) {
      // What the ground absorbs cannot exceed what enters the atmosphere.
      const double absorbed =
          (1.0 - model->atmosphere().ground_albedo[w]) * (sky.value[w] + direct.value[w] * cos_sun);
      EXPECT_LT(absorbed, model->atmosphere().solar_irradiance_w_m2_nm[w] * cos_sun)
          << "sun " << sun_zenith_deg << " wavelength " << model->wavelengths()[w];
    }
  }
}

}  // namespace
}  // namespace clearsky
