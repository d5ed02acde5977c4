// The inverse map and the pixel solid angles of the skydome projections
// (api/skydome/skydome_projection.h): pixel() finds the pixel a direction() came from, and the
// solid angles sum to the sphere (latlong, cubemap) or the hemisphere (fisheye).
#include <gtest/gtest.h>

#include "api/skydome/skydome_projection.h"
#include "models/core/numeric.h"

namespace clearsky::api {
namespace {

TEST(SkydomeProjectionInverse, PixelOfDirectionIsThePixel) {
  for (Projection kind : {Projection::fisheye, Projection::latlong, Projection::cubemap}) {
    const SkydomeProjection p(kind, 64);
    int checked = 0;
    for (int y = 1; y < p.height() - 1; y += 3) {
      for (int x = 1; x < p.width() - 1; x += 3) {
        SkyDirection d;
        if (!p.direction(x, y, d)) continue;
        if (kind == Projection::cubemap &&
            (x % 64 == 0 || x % 64 == 63 || y % 64 == 0 || y % 64 == 63))
          continue;  // cube edges are shared by two faces
        int px = -1, py = -1;
        ASSERT_TRUE(p.pixel(d, px, py));
        EXPECT_EQ(px, x) << static_cast<int>(kind) << " " << y;
        EXPECT_EQ(py, y) << static_cast<int>(kind) << " " << x;
        ++checked;
      }
    }
    EXPECT_GT(checked, 100);
  }
}

TEST(SkydomeProjectionInverse, SolidAnglesCoverTheSphere) {
  const auto total = [](const SkydomeProjection& p) {
    double sum = 0;
    for (int y = 0; y < p.height(); ++y)
      for (int x = 0; x < p.width(); ++x) {
        SkyDirection d;
        if (p.direction(x, y, d)) sum += p.pixel_solid_angle_sr(x, y);
      }
    return sum;
  };
  // latlong: the duplicated seam column adds 1/(width-1); cubemap: the shared edges.
  const SkydomeProjection latlong(Projection::latlong, 512);
  EXPECT_NEAR(total(latlong), 4 * kPi * 512.0 / 511.0, 1e-3);
  const SkydomeProjection cube(Projection::cubemap, 128);
  EXPECT_NEAR(total(cube), 4 * kPi, 4 * kPi * 0.04);
  const SkydomeProjection fisheye(Projection::fisheye, 512);
  EXPECT_NEAR(total(fisheye), 2 * kPi, 2 * kPi * 0.01);
}

}  // namespace
}  // namespace clearsky::api
