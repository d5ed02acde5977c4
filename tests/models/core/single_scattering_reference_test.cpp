// The reference single-scattering integrator against closed forms: zenith view with the sun
// at the zenith (constant total transmittance), nadir view from space in a pure Rayleigh
// atmosphere, and the additivity of aerial perspective.
#include "models/core/single_scattering_reference.h"

#include <gtest/gtest.h>

#include <cmath>

#include "models/atmosphere/phase_functions.h"
#include "models/core/optical_depth.h"
#include "models/core/ray_sphere.h"

namespace clearsky {
namespace {

constexpr double kR = 6360e3, kTop = 6420e3;

AtmosphereSpectra atmosphere_with(double beta) {
  AtmosphereParameters p;
  p.angstrom_beta = beta;
  return AtmosphereSpectra::build(p, WavelengthGrid::paper_bins());
}

TEST(SingleScatteringReference, ZenithViewWithSunAtZenithHasAClosedForm) {
  // Along the vertical, observer-side plus sun-side optical depth is the whole column at every
  // point: L = E exp(-tau) sum_p beta_p,sca P_p(1) H_p (1 - exp(-60 km / H_p)).
  const AtmosphereSpectra a = atmosphere_with(0.04);
  const ScatteringAlongRay s = single_scattering_reference(a, {kR, 1.0, 1.0, 1.0});
  for (std::size_t i = 0; i < s.radiance.size(); ++i) {
    const double column_r = 8000.0 * (1.0 - std::exp(-60.0 / 8.0));
    const double column_m = 1200.0 * (1.0 - std::exp(-50.0));
    const double tau =
        a.rayleigh_scattering_per_m[i] * column_r + a.mie_extinction_per_m[i] * column_m;
    const double expected =
        a.solar_irradiance_w_m2_nm[i] * std::exp(-tau) *
        (a.rayleigh_scattering_per_m[i] * rayleigh_phase(1.0) * column_r +
         a.mie_scattering_per_m[i] * cornette_shanks_phase(1.0, 0.7) * column_m);
    EXPECT_NEAR(s.radiance[i] / expected, 1.0, 1e-10) << i;
    EXPECT_NEAR(s.transmittance[i] / std::exp(-tau), 1.0, 1e-12) << i;
  }
  EXPECT_FALSE(s.hits_ground);
  EXPECT_NEAR(s.length_m, 60e3, 1e-6);
}

TEST(SingleScatteringReference, NadirViewFromSpaceInPureRayleighAtmosphere) {
  // Sun at the zenith, observer above the atmosphere looking straight down, no aerosols:
  // L = E P_R(-1) (1 - exp(-2 tau)) / 2 with tau the Rayleigh column depth.
  const AtmosphereSpectra a = atmosphere_with(0.0);
  const ScatteringAlongRay s = single_scattering_reference(a, {kTop + 300e3, -1.0, 1.0, -1.0});
  EXPECT_TRUE(s.hits_ground);
  for (std::size_t i = 0; i < s.radiance.size(); ++i) {
    const double tau = a.rayleigh_scattering_per_m[i] * 8000.0 * (1.0 - std::exp(-60.0 / 8.0));
    const double expected =
        a.solar_irradiance_w_m2_nm[i] * rayleigh_phase(-1.0) * 0.5 * (1.0 - std::exp(-2.0 * tau));
    EXPECT_NEAR(s.radiance[i] / expected, 1.0, 1e-10) << i;
  }
}

TEST(SingleScatteringReference, AerialPerspectiveIsAdditive) {
  // L(0, D) = L(0, d) + T(0, d) L(d, D) along a low, sun-facing view.
  const AtmosphereSpectra a = atmosphere_with(0.04);
  const RaySunGeometry ray{kR + 200.0, std::cos(degrees_to_radians(85.0)),
                           std::cos(degrees_to_radians(60.0)), std::cos(degrees_to_radians(30.0))};
  const double d = 7000.0;
  const ScatteringAlongRay whole = single_scattering_reference(a, ray);
  const ScatteringAlongRay near = single_scattering_reference(a, ray, d);
  const double r_d = radius_at_distance(ray.r_m, ray.mu, d);
  const RaySunGeometry rest{r_d, mu_at_distance(ray.r_m, ray.mu, d), ray.mu_s_at(d, r_d), ray.nu};
  const ScatteringAlongRay far = single_scattering_reference(a, rest);
  EXPECT_NEAR(near.length_m, d, 1e-9);
  for (std::size_t i = 0; i < whole.radiance.size(); ++i) {
    EXPECT_NEAR((near.radiance[i] + near.transmittance[i] * far.radiance[i]) / whole.radiance[i],
                1.0, 1e-9)
        << i;
    EXPECT_NEAR(near.transmittance[i] * far.transmittance[i] / whole.transmittance[i], 1.0, 1e-9)
        << i;
  }
}

TEST(SingleScatteringReference, FiniteAndNonNegativeInHardCases) {
  const AtmosphereSpectra a = atmosphere_with(0.04);
  struct Case {
    double altitude, view_zenith_deg, sun_zenith_deg, view_sun_deg;
  };
  for (const Case& c :
       {Case{0, 90, 30, 0}, Case{0, 90.0001, 30, 90}, Case{0, 60, 100, 120}, Case{20e3, 95, 95, 5},
        Case{500e3, 110, 80, 40}, Case{500e3, 160, 170, 30}, Case{0, 0, 180, 180}}) {
    const RaySunGeometry ray{kR + c.altitude, std::cos(degrees_to_radians(c.view_zenith_deg)),
                             std::cos(degrees_to_radians(c.sun_zenith_deg)),
                             std::cos(degrees_to_radians(c.view_sun_deg))};
    const ScatteringAlongRay s =
        single_scattering_reference(a, ray, std::numeric_limits<double>::infinity(), {});
    for (std::size_t i = 0; i < s.radiance.size(); ++i) {
      EXPECT_TRUE(is_finite_non_negative(s.radiance[i])) << c.view_zenith_deg << ' ' << i;
      EXPECT_TRUE(is_finite_non_negative(s.transmittance[i]) && s.transmittance[i] <= 1.0);
    }
  }
  // Sun far below the horizon of every point the view crosses: dark.
  const ScatteringAlongRay night = single_scattering_reference(a, {kR, 1.0, -1.0, -1.0});
  for (double v : night.radiance) EXPECT_EQ(v, 0.0);
}

}  // namespace
}  // namespace clearsky
