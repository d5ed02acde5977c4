// RaySunFrame (the sun's trigonometry once per batch) against RaySunGeometry::from, the
// per-view definition: the same expressions, so the same bits.
#include "models/core/ray_sun_frame.h"

#include <gtest/gtest.h>

namespace clearsky {
namespace {

TEST(RaySunFrame, GivesTheRaysOfThePerViewDefinition) {
  const double bottom = 6360e3;
  for (double sun_zenith_deg : {0.0, 31.7, 89.9, 95.0, 180.0}) {
    const SunPosition sun{degrees_to_radians(sun_zenith_deg), 1.234};
    for (double altitude : {0.0, 1234.5, 1e7}) {
      const RaySunFrame frame(bottom, Viewpoint{altitude}, sun);
      for (double zenith_deg = 0.0; zenith_deg <= 180.0; zenith_deg += 7.3) {
        for (double azimuth_deg = -180.0; azimuth_deg <= 360.0; azimuth_deg += 41.0) {
          const ViewDirection view{degrees_to_radians(zenith_deg), degrees_to_radians(azimuth_deg)};
          const RaySunGeometry ray = frame.ray(view);
          const RaySunGeometry expected =
              RaySunGeometry::from(bottom, Viewpoint{altitude}, view, sun);
          EXPECT_EQ(ray.r_m, expected.r_m);
          EXPECT_EQ(ray.mu, expected.mu);
          EXPECT_EQ(ray.mu_s, expected.mu_s);
          EXPECT_EQ(ray.nu, expected.nu) << zenith_deg << " " << azimuth_deg;
        }
      }
    }
  }
}

}  // namespace
}  // namespace clearsky
