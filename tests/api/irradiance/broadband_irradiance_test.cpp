// The broadband extension (api/irradiance/broadband_irradiance.h): a model whose answer is
// SPCTRAL2's own unabsorbed spectrum is continued into SPCTRAL2's broadband figures; the
// absorbers, the altitude and the sun move them the way they must; the models that cannot go
// broadband are named with a reason.
#include "api/irradiance/broadband_irradiance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "models/atmosphere/spctral2.h"
#include "models/bruneton/bruneton.h"
#include "models/core/numeric.h"
#include "models/preetham/preetham.h"

namespace clearsky::api {
namespace {

constexpr double kZenithRad = 0.6;  // about 34 degrees

spctral2::Atmosphere spctral2_of(const BroadbandConditions& c) {
  spctral2::Atmosphere s;
  s.absorbers = {c.atmosphere.precipitable_water_cm, c.atmosphere.ozone_atm_cm};
  s.angstrom_alpha = c.atmosphere.angstrom_alpha;
  s.angstrom_beta = c.atmosphere.angstrom_beta;
  s.aerosol_single_scattering_albedo = c.atmosphere.mie_single_scattering_albedo;
  s.aerosol_asymmetry_g = c.atmosphere.mie_phase_g;
  s.ground_albedo = 0.3;
  return s;
}

// A "model" on 1 nm bins over 360..830 nm answering SPCTRAL2's direct normal or diffuse
// horizontal spectrum without the molecular absorption (which the extension applies).
struct Spctral2Model {
  WavelengthGrid grid = WavelengthGrid::bins(360.0, 1.0, 470);
  std::vector<std::size_t> indices;
  Spectrum direct_normal, diffuse;
  explicit Spctral2Model(const BroadbandConditions& c) {
    const spctral2::Atmosphere s = spctral2_of(c);
    direct_normal = Spectrum(grid.size(), 0.0);
    diffuse = Spectrum(grid.size(), 0.0);
    for (std::size_t i = 0; i < grid.size(); ++i) {
      indices.push_back(i);
      const double t = spctral2::absorption_transmittance(grid[i], s.absorbers, c.sun_zenith_rad,
                                                          s.pressure_ratio);
      const auto e = spctral2::spectral_irradiance(grid[i], c.sun_zenith_rad, s);
      direct_normal[i] = e.direct_normal_w_m2_nm / t;
      diffuse[i] = e.diffuse_horizontal_w_m2_nm / t;
    }
  }
};

BroadbandConditions conditions() {
  BroadbandConditions c;
  c.sun_zenith_rad = kZenithRad;
  c.atmosphere.ground_albedo = 0.3;
  return c;
}

TEST(BroadbandIrradiance, ContinuesSpctral2IntoItsOwnBroadbandFigures) {
  const BroadbandConditions c = conditions();
  const Spctral2Model model(c);
  const spctral2::Atmosphere s = spctral2_of(c);
  double dni = 0.0, dhi = 0.0;
  for (double nm = 300.5; nm < 4000.0; nm += 1.0) {
    const auto e = spctral2::spectral_irradiance(nm, kZenithRad, s);
    dni += e.direct_normal_w_m2_nm;
    dhi += e.diffuse_horizontal_w_m2_nm;
  }
  const BroadbandExtension extension(model.grid, model.indices, c);
  EXPECT_NEAR(extension.direct_normal_w_m2(model.direct_normal) / dni, 1.0, 0.002);
  EXPECT_NEAR(extension.diffuse_w_m2(model.diffuse) / dhi, 1.0, 0.01);
  // Most of the broadband direct beam lies outside the visible range.
  double visible = 0.0;
  for (double v : model.direct_normal) visible += v;
  EXPECT_GT(dni, 1.6 * visible);
}

TEST(BroadbandIrradiance, DirectNormalFallsWithWaterAndOzoneAndRisesWithAltitude) {
  BroadbandConditions c = conditions();
  const Spctral2Model model(c);
  const auto dni = [&](const BroadbandConditions& k) {
    return BroadbandExtension(model.grid, model.indices, k).direct_normal_w_m2(model.direct_normal);
  };
  const double reference = dni(c);
  BroadbandConditions wet = c;
  wet.atmosphere.precipitable_water_cm = 4.0;
  EXPECT_LT(dni(wet), reference - 20.0);
  BroadbandConditions dry = c;
  dry.atmosphere.precipitable_water_cm = 0.2;
  EXPECT_GT(dni(dry), reference + 20.0);
  BroadbandConditions more_ozone = c;
  more_ozone.atmosphere.ozone_atm_cm = 0.5;
  EXPECT_LT(dni(more_ozone), reference);
  BroadbandConditions high = c;
  high.altitude_m = 2000.0;
  EXPECT_GT(dni(high), reference);
  BroadbandConditions perihelion = c;
  perihelion.earth_sun_distance_factor = 1.0342;
  EXPECT_NEAR(dni(perihelion) / reference, 1.0342, 1e-12);
  BroadbandConditions night = c;
  night.sun_zenith_rad = degrees_to_radians(95.0);
  EXPECT_EQ(dni(night), 0.0);
}

TEST(BroadbandIrradiance, DiffuseOutsideTheRangeFollowsTheModelsLevel) {
  const BroadbandConditions c = conditions();
  const Spctral2Model model(c);
  const BroadbandExtension extension(model.grid, model.indices, c);
  const double reference = extension.diffuse_w_m2(model.diffuse);
  // A model whose sky is twice as bright has twice the broadband diffuse: the extension is
  // scaled to the model at its range ends.
  Spectrum doubled = model.diffuse * 2.0;
  EXPECT_NEAR(extension.diffuse_w_m2(doubled) / reference, 2.0, 1e-9);
}

TEST(BroadbandIrradiance, NamesTheModelsThatCannotGoBroadband) {
  EXPECT_FALSE(broadband_unavailable_reason(bruneton_descriptor()));
  const auto reason = broadband_unavailable_reason(preetham_descriptor());
  ASSERT_TRUE(reason);
  EXPECT_NE(reason->find("preetham"), std::string::npos);
  EXPECT_NE(reason->find("turbidity"), std::string::npos);
}

TEST(BroadbandIrradiance, DayOfYear) {
  // 2013-05-27T15:45:00Z is day 147 of 2013, 15.75 h into it.
  EXPECT_NEAR(day_of_year_utc(1369669500.0), 147.0 + 15.75 / 24.0, 1e-9);
  EXPECT_NEAR(day_of_year_utc(1356998400.0), 1.0, 1e-12);  // 2013-01-01T00:00:00Z
}

}  // namespace
}  // namespace clearsky::api
