// Skydome pixel directions: the fisheye's centre, horizon circle and orientation (North up,
// East left); latlong and cubemap agree with OpenEXR's own direction -> pixel maps.
#include "api/skydome/skydome_projection.h"

#include <OpenEXR/ImfEnvmap.h>
#include <gtest/gtest.h>

#include "api/skydome/skydome_render.h"

namespace clearsky::api {
namespace {

TEST(SkydomeProjection, FisheyeIsEquidistantNorthUpEastLeft) {
  const SkydomeProjection p(Projection::fisheye, 100);
  SkyDirection d;
  ASSERT_TRUE(p.direction(50, 50, d));  // centre (pixel centre at 50.5, 50.5)
  EXPECT_NEAR(d.zenith_rad, std::sqrt(2.0) * 0.01 * kPi / 2, 1e-12);
  ASSERT_TRUE(p.direction(50, 0, d));  // top: North near the horizon
  EXPECT_NEAR(d.zenith_rad, 0.98 * kPi / 2, 0.02);
  EXPECT_NEAR(d.azimuth_rad, 0.0, 0.02);
  ASSERT_TRUE(p.direction(0, 49, d));  // left: East
  EXPECT_NEAR(d.azimuth_rad, kPi / 2, 0.02);
  ASSERT_TRUE(p.direction(99, 49, d));  // right: West
  EXPECT_NEAR(d.azimuth_rad, -kPi / 2, 0.02);
  EXPECT_FALSE(p.direction(0, 0, d));  // corner: outside the circle
}

// latlong_row_below_horizon() decides a row from its first pixel: every pixel of the row must
// agree with direction(), at even and odd heights (a row on the horizon itself) and large sizes.
TEST(SkydomeProjection, LatlongRowsAreWhollyOnOneSideOfTheHorizon) {
  for (int size : {8, 10, 48, 258, 1024}) {
    const SkydomeProjection p(Projection::latlong, size);
    int below = 0;
    for (int y = 0; y < p.height(); ++y) {
      const bool row_below = p.latlong_row_below_horizon(y);
      below += row_below ? 1 : 0;
      for (int x = 0; x < p.width(); ++x) {
        SkyDirection d;
        ASSERT_TRUE(p.direction(x, y, d));
        ASSERT_EQ(d.zenith_rad > 0.5 * kPi, row_below) << size << ": " << x << "," << y;
      }
    }
    EXPECT_EQ(below, p.height() / 2) << size;
  }
  EXPECT_FALSE(SkydomeProjection(Projection::fisheye, 64).latlong_row_below_horizon(60));
  EXPECT_FALSE(SkydomeProjection(Projection::cubemap, 16).latlong_row_below_horizon(50));
}

TEST(SkydomeProjection, EnvironmentMapsMatchOpenExr) {
  for (Projection kind : {Projection::latlong, Projection::cubemap}) {
    const SkydomeProjection p(kind, 32);
    const IMATH_NAMESPACE::Box2i dw({0, 0}, {p.width() - 1, p.height() - 1});
    for (int y = 0; y < p.height(); y += 3) {
      for (int x = 0; x < p.width(); x += 5) {
        SkyDirection d;
        ASSERT_TRUE(p.direction(x, y, d));
        const Vec3 v = d.unit_vector();
        const IMATH_NAMESPACE::V3f exr(static_cast<float>(-v.x), static_cast<float>(v.z),
                                       static_cast<float>(v.y));
        IMATH_NAMESPACE::V2f back;
        if (kind == Projection::latlong) {
          back = Imf::LatLongMap::pixelPosition(dw, exr);
          // The poles have no longitude; the first and last columns are the same meridian.
          if (y == 0 || y == p.height() - 1 || x == 0 || x == p.width() - 1) continue;
        } else {
          Imf::CubeMapFace face;
          IMATH_NAMESPACE::V2f pif;
          Imf::CubeMap::faceAndPixelPosition(exr, dw, face, pif);
          back = Imf::CubeMap::pixelPosition(face, dw, pif);
          if (x == 0 || y % 32 == 0 || x == 31 || y % 32 == 31) continue;  // face edges are shared
        }
        EXPECT_NEAR(back.x, x, 1e-2) << x << "," << y;
        EXPECT_NEAR(back.y, y, 1e-2) << x << "," << y;
      }
    }
  }
  // OpenEXR's latlong: pixel x at longitude -2 pi (x / (w - 1) - 1/2), y at latitude
  // -pi (y / (h - 1) - 1/2); longitude 0 is North, positive longitudes West.
  const SkydomeProjection latlong(Projection::latlong, 64);
  SkyDirection d;
  latlong.direction(48, 16, d);  // right of the centre: towards East
  EXPECT_NEAR(d.azimuth_rad, 2 * kPi * (48.0 / 63 - 0.5), 1e-6);
  EXPECT_NEAR(d.zenith_rad, kPi / 2 + kPi * (16.0 / 31 - 0.5), 1e-6);
  latlong.direction(16, 10, d);  // left of the centre: towards West
  EXPECT_NEAR(d.azimuth_rad, 2 * kPi * (16.0 / 63 - 0.5), 1e-6);
  latlong.direction(10, 0, d);
  EXPECT_NEAR(d.zenith_rad, 0.0, 1e-6);
}

TEST(SkydomeProjection, SpectralChannelNamesFollowFichet2021) {
  EXPECT_EQ(spectral_channel_name(550.0), "S0.550,000000nm");
  EXPECT_EQ(spectral_channel_name(371.75), "S0.371,750000nm");
}

}  // namespace
}  // namespace clearsky::api
