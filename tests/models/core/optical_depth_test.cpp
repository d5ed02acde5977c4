// Optical lengths and transmittance against closed forms: the vertical exponential layer, the
// Chapman function at grazing incidence, rays from above the atmosphere.
#include "models/core/optical_depth.h"

#include <gtest/gtest.h>

#include <cmath>

#include "models/core/numeric.h"
#include "models/core/ray_sphere.h"

namespace clearsky {
namespace {

constexpr double kR = 6360e3, kTop = 6420e3;

AtmosphereSpectra paper_atmosphere() {
  return AtmosphereSpectra::build({}, WavelengthGrid::paper_bins());
}

TEST(OpticalDepth, VerticalRayMatchesClosedFormForBothScaleHeights) {
  for (double h : {1200.0, 8000.0}) {
    const double exact = vertical_optical_length_m(0.0, kTop - kR, h);
    EXPECT_NEAR(
        exponential_optical_length_m(kR, 1.0, kTop - kR, kR, h, RayQuadratureOptions::reference()) /
            exact,
        1.0, 1e-13);
    EXPECT_NEAR(exponential_optical_length_m(kR, 1.0, kTop - kR, kR, h) / exact, 1.0, 1e-8);
    // Downwards from 10 km to the ground.
    EXPECT_NEAR(exponential_optical_length_m(kR + 10e3, -1.0, 10e3, kR, h) /
                    vertical_optical_length_m(0.0, 10e3, h),
                1.0, 1e-8);
  }
}

TEST(OpticalDepth, VerticalTransmittanceIsExpOfColumnDepth) {
  // tau = k H (1 - exp(-Htop / H)) for each profile (docs/conventions.md "Physical identities").
  const AtmosphereSpectra atmosphere = paper_atmosphere();
  const Spectrum t = transmittance_to_space(atmosphere, kR, 1.0, RayQuadratureOptions::reference());
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double tau =
        atmosphere.rayleigh_scattering_per_m[i] * 8000.0 * (1.0 - std::exp(-60.0 / 8.0)) +
        atmosphere.mie_extinction_per_m[i] * 1200.0 * (1.0 - std::exp(-50.0));
    EXPECT_NEAR(t[i] / std::exp(-tau), 1.0, 1e-12) << i;
  }
}

TEST(OpticalDepth, HorizontalRayMatchesChapmanAsymptotics) {
  // Ch(x, 90 deg) = x e^x K_1(x) ~ sqrt(pi x / 2) (1 + 3/(8x) - 15/(128 x^2) + 315/(3072 x^3)),
  // x = R/H (Hankel's expansion of K_1); the ray
  // runs far enough (2000 km) for the exponential tail to vanish.
  for (double h : {1200.0, 8000.0}) {
    const double x = kR / h;
    const double chapman =
        std::sqrt(kPi * x / 2.0) *
        (1.0 + 3.0 / (8.0 * x) - 15.0 / (128.0 * x * x) + 315.0 / (3072.0 * x * x * x));
    const double length =
        exponential_optical_length_m(kR, 0.0, 2000e3, kR, h, RayQuadratureOptions::reference());
    EXPECT_NEAR(length / (h * chapman), 1.0, 1e-10) << h;
  }
}

TEST(OpticalDepth, ChordFromSpaceIsTwiceTheHalfChordFromTheTangentPoint) {
  const AtmosphereSpectra atmosphere = paper_atmosphere();
  const double r = kTop + 500e3;
  for (double tangent_altitude : {1.0, 100.0, 5000.0, 30000.0}) {
    const double c = kR + tangent_altitude;
    const double mu = -std::sqrt(1.0 - (c / r) * (c / r));
    const auto chord =
        optical_lengths_to_space(atmosphere, r, mu, RayQuadratureOptions::reference());
    ASSERT_TRUE(chord.has_value());
    const OpticalLengths half =
        optical_lengths(atmosphere, c, 0.0, distance_to_sphere_from_inside(c, 0.0, kTop),
                        RayQuadratureOptions::reference());
    EXPECT_NEAR(chord->rayleigh_m / (2.0 * half.rayleigh_m), 1.0, 1e-8) << tangent_altitude;
    EXPECT_NEAR(chord->mie_m / (2.0 * half.mie_m), 1.0, 1e-8) << tangent_altitude;
  }
}

TEST(OpticalDepth, ObserverAboveTheAtmosphere) {
  const AtmosphereSpectra atmosphere = paper_atmosphere();
  const double r = kTop + 1000e3;
  // Looking up or past the atmosphere: nothing in the way.
  const Spectrum up = transmittance_to_space(atmosphere, r, 1.0);
  for (double v : up) EXPECT_EQ(v, 1.0);
  const double misses = -std::sqrt(1.0 - (kTop * 1.0001 / r) * (kTop * 1.0001 / r));
  for (double v : transmittance_to_space(atmosphere, r, misses)) EXPECT_EQ(v, 1.0);
  // Looking at the Earth: shadowed.
  EXPECT_FALSE(optical_lengths_to_space(atmosphere, r, -1.0).has_value());
  for (double v : transmittance_to_space(atmosphere, r, -1.0)) EXPECT_EQ(v, 0.0);
}

TEST(OpticalDepth, GroundShadowBoundaryAtTheGeometricHorizon) {
  for (double altitude : {0.0, 10.0, 1e4, 1e6}) {
    const double r = kR + altitude;
    const double horizon = -std::sqrt(std::max(0.0, 1.0 - (kR / r) * (kR / r)));
    EXPECT_FALSE(ray_hits_ground(r, horizon + 1e-9, kR)) << altitude;
    EXPECT_TRUE(ray_hits_ground(r, horizon - 1e-9, kR)) << altitude;
  }
  EXPECT_FALSE(ray_hits_ground(kR, 0.0, kR));
}

TEST(OpticalDepth, GrazingTransmittanceIsTinyButFiniteAndContinuous) {
  const AtmosphereSpectra atmosphere = paper_atmosphere();
  // Just above the horizon from 1 km: the ray skims the ground; transmittance is continuous
  // in mu and falls towards 0 near the shadow boundary.
  const double r = kR + 1000.0;
  const double horizon = -std::sqrt(1.0 - (kR / r) * (kR / r));
  double previous = -1.0;
  for (double dmu = 1e-3; dmu >= 1e-7; dmu /= 10.0) {
    const auto lengths = optical_lengths_to_space(atmosphere, r, horizon + dmu);
    ASSERT_TRUE(lengths.has_value());
    EXPECT_TRUE(std::isfinite(lengths->rayleigh_m) && lengths->rayleigh_m > 0.0);
    if (previous > 0.0) {
      EXPECT_GE(lengths->rayleigh_m, previous * (1.0 - 1e-9));
      EXPECT_LT(lengths->rayleigh_m, previous * 1.2);
    }
    previous = lengths->rayleigh_m;
  }
}

}  // namespace
}  // namespace clearsky
