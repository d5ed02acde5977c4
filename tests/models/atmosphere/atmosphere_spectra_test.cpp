// The paper's atmosphere on the 40-bin grid: values quoted in docs/architecture.md
// "The atmosphere".
#include "models/atmosphere/atmosphere_spectra.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace clearsky {
namespace {

TEST(AtmosphereSpectra, PaperDefaults) {
  const AtmosphereParameters p;
  EXPECT_EQ(p.earth_radius_m, 6360e3);
  EXPECT_EQ(p.top_radius_m, 6420e3);
  EXPECT_EQ(p.rayleigh_scale_height_m, 8000.0);
  EXPECT_EQ(p.mie_scale_height_m, 1200.0);
  EXPECT_EQ(p.angstrom_alpha, 0.8);
  EXPECT_EQ(p.angstrom_beta, 0.04);
  EXPECT_EQ(p.mie_single_scattering_albedo, 0.8);
  EXPECT_EQ(p.mie_phase_g, 0.7);
  EXPECT_EQ(p.turbidity, 2.53);
  EXPECT_FALSE(p.ground_albedo.has_value());
}

TEST(AtmosphereSpectra, RayleighAt15CelsiusMatchesTheStudy) {
  const WavelengthGrid grid = WavelengthGrid::points({360.0, 501.0});
  const AtmosphereSpectra s = AtmosphereSpectra::build({}, grid);
  EXPECT_NEAR(s.rayleigh_scattering_per_m[0], 6.678e-5, 0.002e-5);
  EXPECT_NEAR(s.rayleigh_scattering_per_m[1], 1.702e-5, 0.002e-5);
}

TEST(AtmosphereSpectra, MieFollowsAngstrom) {
  const WavelengthGrid grid = WavelengthGrid::points({500.0, 1000.0});
  const AtmosphereSpectra s = AtmosphereSpectra::build({}, grid);
  EXPECT_DOUBLE_EQ(s.mie_extinction_per_m[1], 0.04 / 1200.0);
  EXPECT_DOUBLE_EQ(s.mie_extinction_per_m[0], 0.04 * std::pow(0.5, -0.8) / 1200.0);
  EXPECT_DOUBLE_EQ(s.mie_scattering_per_m[0], 0.8 * s.mie_extinction_per_m[0]);
}

TEST(AtmosphereSpectra, GrassAlbedoIsHeldBeyond800Nm) {
  const AtmosphereSpectra s = AtmosphereSpectra::build({}, WavelengthGrid::points({800.0, 818.25}));
  EXPECT_DOUBLE_EQ(s.ground_albedo[0], s.ground_albedo[1]);
  AtmosphereParameters constant;
  constant.ground_albedo = 0.3;
  EXPECT_DOUBLE_EQ(
      AtmosphereSpectra::build(constant, WavelengthGrid::paper_bins()).ground_albedo[5], 0.3);
}

TEST(AtmosphereParameters, ValidationNamesTheParameterAndRejectsNaN) {
  AtmosphereParameters p;
  p.angstrom_beta = std::numeric_limits<double>::quiet_NaN();
  try {
    p.validate();
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("beta", 0), 0u) << e.what();
  }
  p = {};
  p.mie_phase_g = 1.0;
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p = {};
  p.top_radius_m = p.earth_radius_m;
  EXPECT_THROW(p.validate(), std::invalid_argument);
  EXPECT_NE(AtmosphereParameters{}.canonical_string(), p.canonical_string());
}

}  // namespace
}  // namespace clearsky
