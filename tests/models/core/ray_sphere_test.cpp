// Ray/sphere distances: closed forms, grazing rays, observers above the atmosphere.
#include "models/core/ray_sphere.h"

#include <gtest/gtest.h>

namespace clearsky {
namespace {

constexpr double kBottom = 6360e3, kTop = 6420e3;

TEST(RaySphere, VerticalRaysCrossTheShellThickness) {
  EXPECT_NEAR(distance_to_sphere_from_inside(kBottom, 1.0, kTop), 60e3, 1e-6);
  EXPECT_NEAR(distance_to_sphere_from_outside(kTop, -1.0, kBottom), 60e3, 1e-6);
  EXPECT_FALSE(std::isfinite(distance_to_sphere_from_outside(kTop, 0.1, kBottom)));
}

TEST(RaySphere, HorizontalRayFromTheGroundReachesTheTopAtTheTangentLength) {
  const double expected = std::sqrt(kTop * kTop - kBottom * kBottom);
  EXPECT_NEAR(distance_to_sphere_from_inside(kBottom, 0.0, kTop), expected, 1e-6);
  const AtmosphereSegment s = atmosphere_segment(kBottom, 0.0, kBottom, kTop);
  EXPECT_FALSE(s.hits_ground);
  EXPECT_NEAR(s.end, expected, 1e-6);
}

TEST(RaySphere, GrazingTheGroundFromAltitude) {
  // From 10 km, the ray tangent to the ground has mu = -sqrt(1 - (R/r)^2).
  const double r = kBottom + 10e3;
  const double mu_horizon = -std::sqrt(1.0 - (kBottom / r) * (kBottom / r));
  const AtmosphereSegment below = atmosphere_segment(r, mu_horizon - 1e-9, kBottom, kTop);
  const AtmosphereSegment above = atmosphere_segment(r, mu_horizon + 1e-9, kBottom, kTop);
  EXPECT_TRUE(below.hits_ground);
  EXPECT_FALSE(above.hits_ground);
  EXPECT_NEAR(below.end, std::sqrt(r * r - kBottom * kBottom), 200.0);
  EXPECT_TRUE(std::isfinite(above.end));
}

TEST(RaySphere, ObserverInSpace) {
  const double r = kTop + 100e3;
  const AtmosphereSegment down = atmosphere_segment(r, -1.0, kBottom, kTop);
  EXPECT_NEAR(down.start, 100e3, 1e-6);
  EXPECT_NEAR(down.end, 160e3, 1e-6);
  EXPECT_TRUE(down.hits_ground);
  const AtmosphereSegment up = atmosphere_segment(r, 0.5, kBottom, kTop);
  EXPECT_EQ(up.start, up.end);
  // A limb ray crossing the shell only.
  const double mu_limb = -std::sqrt(1.0 - std::pow((kBottom + 30e3) / r, 2));
  const AtmosphereSegment limb = atmosphere_segment(r, mu_limb, kBottom, kTop);
  EXPECT_FALSE(limb.hits_ground);
  EXPECT_GT(limb.end, limb.start);
  EXPECT_NEAR(radius_at_distance(r, mu_limb, 0.5 * (limb.start + limb.end)), kBottom + 30e3, 1.0);
}

TEST(RaySphere, RadiusAndCosineAlongARay) {
  EXPECT_NEAR(radius_at_distance(kBottom, 1.0, 1000.0), kBottom + 1000.0, 1e-6);
  EXPECT_NEAR(mu_at_distance(kBottom, 0.0, 0.0), 0.0, 1e-15);
  EXPECT_GT(mu_at_distance(kBottom, 0.0, 100e3), 0.0);
}

}  // namespace
}  // namespace clearsky
