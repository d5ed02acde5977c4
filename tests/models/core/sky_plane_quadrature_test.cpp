// The sky-plane quadrature (models/core/sky_plane_quadrature.h): a uniform sky of radiance 1
// gives the view-factor irradiance pi (1 + cos tilt) / 2 on any plane, every direction lies
// above the horizon and in front of the plane, and a downward plane sees nothing.
#include "models/core/sky_plane_quadrature.h"

#include <gtest/gtest.h>

#include <cmath>

namespace clearsky {
namespace {

TEST(SkyPlaneQuadrature, UniformSkyGivesTheViewFactor) {
  for (double tilt_deg : {0.0, 1e-3, 10.0, 45.0, 90.0, 135.0, 179.0}) {
    for (double azimuth_deg : {0.0, 77.0, 200.0}) {
      const PlaneOrientation plane{degrees_to_radians(tilt_deg), degrees_to_radians(azimuth_deg)};
      const WeightedDirections rule = sky_plane_quadrature(plane, 12, 16);
      const Vec3 n = SkyDirection{plane.tilt_rad, plane.azimuth_rad}.unit_vector();
      double sum = 0.0;
      for (std::size_t i = 0; i < rule.views.size(); ++i) {
        ASSERT_GT(rule.weights[i], 0.0);
        ASSERT_LT(rule.views[i].zenith_rad, 0.5 * kPi);
        ASSERT_GT(dot(rule.views[i].unit_vector(), n), 0.0);
        sum += rule.weights[i];
      }
      EXPECT_NEAR(sum, kPi * (1.0 + std::cos(plane.tilt_rad)) / 2.0, 1e-12)
          << tilt_deg << " " << azimuth_deg;
    }
  }
  EXPECT_TRUE(sky_plane_quadrature({kPi, 0.0}, 12, 16).views.empty());
}

TEST(SkyPlaneQuadrature, IntegratesTheCosineOfTheViewZenithExactly) {
  // L = cos(theta) on a vertical plane: integral of cos(theta) (d . n) over the quarter
  // sphere = integral of sin^3(alpha) x integral of cos(psi) sin(psi) = 4/3 x 1/2.
  const WeightedDirections rule = sky_plane_quadrature({0.5 * kPi, 0.0}, 16, 8);
  double sum = 0.0;
  for (std::size_t i = 0; i < rule.views.size(); ++i)
    sum += rule.weights[i] * std::cos(rule.views[i].zenith_rad);
  EXPECT_NEAR(sum, 2.0 / 3.0, 1e-12);
}

}  // namespace
}  // namespace clearsky
