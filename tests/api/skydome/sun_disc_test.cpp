// The solar disc of a skydome (api/skydome/sun_disc.h): its pixels carry the direct normal
// irradiance at every wavelength in every projection, whatever the pixel size against the disc;
// the limb darkening law; a disc below the horizon carries nothing.
#include "api/skydome/sun_disc.h"

#include <gtest/gtest.h>

#include "models/core/numeric.h"

namespace clearsky::api {
namespace {

// sum over the disc's pixels of radiance x solid angle, per wavelength.
std::vector<double> carried(const SolarDiscPixels& disc, const SkydomeProjection& projection,
                            std::size_t n) {
  std::vector<double> sum(n, 0.0);
  for (const auto& p : disc.pixels())
    for (std::size_t w = 0; w < n; ++w)
      sum[w] += p.radiance[w] * projection.pixel_solid_angle_sr(p.x, p.y);
  return sum;
}

TEST(SunDisc, PixelsCarryTheDirectIrradianceInEveryProjection) {
  const std::vector<double> nm{380.0, 550.0, 700.0, 900.0};
  const std::vector<double> e{0.5, 1.5, 1.2, 0.8};  // W/(m2.nm)
  const SkyDirection sun{degrees_to_radians(40.0), degrees_to_radians(130.0)};
  for (Projection kind : {Projection::fisheye, Projection::latlong, Projection::cubemap}) {
    for (int size : {16, 256, 4096}) {
      const SkydomeProjection projection(kind, size);
      const SolarDiscPixels disc(projection, sun, nm, e);
      ASSERT_FALSE(disc.pixels().empty());
      const auto sum = carried(disc, projection, nm.size());
      for (std::size_t w = 0; w < nm.size(); ++w)
        EXPECT_NEAR(sum[w], e[w], 1e-9 * e[w]) << static_cast<int>(kind) << " " << size;
      // Small images: the disc falls in one or a few pixels; large ones: many.
      if (size == 16) {
        EXPECT_LE(disc.pixels().size(), 4u);
      }
      if (size == 4096) {
        EXPECT_GE(disc.pixels().size(), 20u);
      }
      // The disc is around the sun's pixel.
      int x = 0, y = 0;
      ASSERT_TRUE(projection.pixel(sun, x, y));
      EXPECT_NE(disc.find(x, y), nullptr);
    }
  }
}

TEST(SunDisc, CentreIsBrighterThanTheLimb) {
  // Neckel and Labs 1994: 1 at the centre, darker towards the limb, more so in the blue.
  for (double nm : {320.0, 450.0, 550.0, 720.0}) {
    EXPECT_NEAR(solar_limb_darkening(nm, 1.0), 1.0, 0.01) << nm;
    EXPECT_LT(solar_limb_darkening(nm, 0.2), solar_limb_darkening(nm, 0.8)) << nm;
  }
  EXPECT_LT(solar_limb_darkening(400.0, 0.3), solar_limb_darkening(700.0, 0.3));
  // Large image: the pixel at the disc centre is brighter than one at its rim.
  const SkydomeProjection projection(Projection::cubemap, 4096);
  const SkyDirection sun{degrees_to_radians(30.0), degrees_to_radians(200.0)};
  const SolarDiscPixels disc(projection, sun, std::vector<double>{550.0}, std::vector<double>{1.0});
  double brightest = 0, dimmest = 1e300;
  for (const auto& p : disc.pixels()) {
    brightest = std::max(brightest, p.radiance[0]);
    dimmest = std::min(dimmest, p.radiance[0]);
  }
  // The mean disc radiance is E / Omega_disc; the centre is above it.
  EXPECT_GT(brightest, 1.0 / sun_disc_solid_angle_sr());
  EXPECT_LT(dimmest, 0.5 * brightest);
}

TEST(SunDisc, HiddenBelowTheHorizon) {
  const SkydomeProjection projection(Projection::latlong, 1024);
  const std::vector<double> nm{550.0}, e{1.0};
  EXPECT_TRUE(SolarDiscPixels(projection, SkyDirection{degrees_to_radians(90.5), 0.0}, nm, e)
                  .pixels()
                  .empty());
  // Centred on the horizon: half of it is above.
  const SolarDiscPixels half(projection, SkyDirection{degrees_to_radians(90.0), 0.0}, nm, e);
  const double sum = carried(half, projection, 1)[0];
  EXPECT_NEAR(sum, 0.5, 0.03);
}

}  // namespace
}  // namespace clearsky::api
