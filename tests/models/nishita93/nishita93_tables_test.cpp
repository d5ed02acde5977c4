// Nishita93's tables: spheres of equal Rayleigh density steps, optical lengths against the
// closed form of the vertical layer and the reference integration, the Earth's shadow.
#include "models/nishita93/nishita93_tables.h"

#include <gtest/gtest.h>

#include <cmath>

#include "models/core/numeric.h"

namespace clearsky {
namespace {

constexpr double kR = 6360e3, kTop = 6420e3;

const Nishita93Tables& paper_tables() {
  static const Nishita93Tables tables = Nishita93Tables::build({}, 64, 64);
  return tables;
}

TEST(Nishita93Tables, SpheresAreEqualStepsOfRayleighDensityFromGroundToTop) {
  const Nishita93Tables& t = paper_tables();
  EXPECT_EQ(t.sphere_radius_m(0), kR);
  EXPECT_EQ(t.sphere_radius_m(63), kTop);
  const double a = std::exp(-60.0 / 8.0) - 1.0;
  for (int i = 0; i < 64; ++i) {
    EXPECT_NEAR(t.sphere_rayleigh_density(i), 1.0 + a * i / 63.0, 1e-13) << i;
    if (i > 0) {
      EXPECT_GT(t.sphere_radius_m(i), t.sphere_radius_m(i - 1));
    }
  }
  // The first layer is thin (128 m) where the air is densest.
  EXPECT_NEAR(t.sphere_radius_m(1) - kR, 127.9, 0.1);
}

TEST(Nishita93Tables, VerticalColumnMatchesTheClosedFormWithinTheTrapezoidError) {
  // Cylinder 0 is the axis: the vertical ray. The trapezoid over 63 layers overestimates the
  // convex exponential, by 1.3 % for Rayleigh (the top layer spans 33 to 60 km).
  const Nishita93Tables& t = paper_tables();
  for (int i : {0, 10, 40}) {
    const double h = t.sphere_radius_m(i) - kR;
    const OpticalLengths l = t.node(i, 0, false);
    const double rayleigh = vertical_optical_length_m(h, 60e3, 8000.0);
    const double mie = vertical_optical_length_m(h, 60e3, 1200.0);
    EXPECT_GT(l.rayleigh_m, rayleigh);
    EXPECT_LT(l.rayleigh_m / rayleigh - 1.0, 0.015 * (1.0 + i / 10.0)) << i;
    EXPECT_GT(l.mie_m, mie);
    EXPECT_LT(l.mie_m / mie - 1.0, 0.02 * (1.0 + i / 10.0)) << i;
  }
}

TEST(Nishita93Tables, LookupsMatchTheReferenceWithinTheDiscretisationError) {
  // In the lowest 3 km and for the sun up to 72 degrees from the zenith (where the sky's light
  // comes from): within 3 % (Rayleigh) and 5 % (Mie). Higher up the few upper layers of the
  // trapezoid, and nearer the horizon the 1/63 cylinder spacing, bring it to about 20 % (15 km, 80 degrees).
  const Nishita93Tables& t = paper_tables();
  const AtmosphereSpectra atmosphere = AtmosphereSpectra::build({}, WavelengthGrid::paper_bins());
  for (double altitude : {0.0, 700.0, 3000.0, 15000.0}) {
    for (double mu : {1.0, 0.8, 0.5, 0.3, 0.18}) {
      const auto fast = t.sun_optical_lengths(kR + altitude, mu);
      const auto exact = optical_lengths_to_space(atmosphere, kR + altitude, mu,
                                                  RayQuadratureOptions::reference());
      ASSERT_TRUE(fast && exact);
      const bool well_resolved = altitude <= 3000.0 && mu >= 0.3;
      EXPECT_NEAR(fast->rayleigh_m / exact->rayleigh_m, 1.0, well_resolved ? 0.03 : 0.25)
          << altitude << ' ' << mu;
      EXPECT_NEAR(fast->mie_m / exact->mie_m, 1.0, well_resolved ? 0.05 : 0.25)
          << altitude << ' ' << mu;
    }
  }
}

TEST(Nishita93Tables, AgainstTheAxisFollowsTheChordThroughTheTangentPoint) {
  // The last cylinder is horizontal at every sphere: both directions hold the same values
  // there (the tangent point is the point itself).
  const Nishita93Tables& t = paper_tables();
  for (int i : {0, 20, 63}) {
    const OpticalLengths along = t.node(i, 63, false), against = t.node(i, 63, true);
    EXPECT_DOUBLE_EQ(along.rayleigh_m, against.rayleigh_m) << i;
    EXPECT_DOUBLE_EQ(along.mie_m, against.mie_m) << i;
  }
  // Downward rays hold more air than upward ones from the same point.
  for (int j = 0; j < 63; ++j)
    EXPECT_GT(t.node(30, j, true).rayleigh_m, t.node(30, j, false).rayleigh_m) << j;
}

TEST(Nishita93Tables, TheEarthShadowsTheSun) {
  const Nishita93Tables& t = paper_tables();
  EXPECT_FALSE(t.sun_optical_lengths(kR, -0.01).has_value());
  EXPECT_FALSE(t.sun_optical_lengths(kR + 10e3, -0.2).has_value());
  EXPECT_TRUE(t.sun_optical_lengths(kR + 10e3, -0.05).has_value());  // horizon at mu = -0.056
  // From above the atmosphere: nothing in the way upwards, the atmosphere crossed when the
  // sun is seen through the limb, the Earth in the way below that.
  const auto up = t.sun_optical_lengths(kTop + 100e3, 0.3);
  ASSERT_TRUE(up.has_value());
  EXPECT_EQ(up->rayleigh_m, 0.0);
  const double r = kTop + 100e3, limb = -std::sqrt(1.0 - std::pow((kR + 20e3) / r, 2));
  const auto through = t.sun_optical_lengths(r, limb);
  ASSERT_TRUE(through.has_value());
  EXPECT_GT(through->rayleigh_m, 0.0);
  EXPECT_FALSE(t.sun_optical_lengths(r, -1.0).has_value());
}

TEST(Nishita93Tables, RefusesDegenerateSizes) {
  EXPECT_THROW(Nishita93Tables::build({}, 1, 64), std::invalid_argument);
  EXPECT_THROW(Nishita93Tables::build({}, 64, 1), std::invalid_argument);
}

}  // namespace
}  // namespace clearsky
