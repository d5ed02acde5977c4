// Radiance's RGB (api/colour/radiance_rgb.h): the equal-energy white has R = G = B, the
// luminance row is Radiance's 0.265, 0.670, 0.065, and 179 lm/W times it gives back 683 Y.
#include "api/colour/radiance_rgb.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace clearsky::api {
namespace {

TEST(RadianceRgb, EqualEnergyWhiteIsNeutral) {
  const RadianceRgb white = xyz_to_radiance_rgb({1.0, 1.0, 1.0});
  const double k = kMaxLuminousEfficacy / kRadianceWhiteEfficacy;
  EXPECT_NEAR(white.r, k, 1e-12);
  EXPECT_NEAR(white.g, k, 1e-12);
  EXPECT_NEAR(white.b, k, 1e-12);
}

TEST(RadianceRgb, LuminanceRowIsRadiances) {
  // The luminance of a unit primary, over 179: Radiance's CIE_rf, CIE_gf, CIE_bf.
  EXPECT_NEAR(radiance_rgb_luminance({1, 0, 0}) / kRadianceWhiteEfficacy, 0.265, 5e-4);
  EXPECT_NEAR(radiance_rgb_luminance({0, 1, 0}) / kRadianceWhiteEfficacy, 0.670, 5e-4);
  EXPECT_NEAR(radiance_rgb_luminance({0, 0, 1}) / kRadianceWhiteEfficacy, 0.065, 5e-4);
}

TEST(RadianceRgb, KeepsTheLuminance) {
  for (const Xyz xyz : {Xyz{0.3, 0.4, 0.5}, Xyz{2.0, 1.5, 0.2}, Xyz{0.01, 0.02, 0.09}}) {
    const RadianceRgb rgb = xyz_to_radiance_rgb(xyz);
    EXPECT_NEAR(radiance_rgb_luminance(rgb), kMaxLuminousEfficacy * xyz.y, 1e-9);
  }
}

TEST(RadianceRgb, NegativeComponentsAreClippedAndFlagged) {
  // A saturated blue-violet outside the primaries' triangle.
  const RadianceRgb outside = xyz_to_radiance_rgb({0.2, 0.02, 1.2});
  EXPECT_LT(std::min({outside.r, outside.g, outside.b}), 0.0);
  const ClippedRadianceRgb clipped = clip_radiance_rgb(outside);
  EXPECT_TRUE(clipped.clipped);
  EXPECT_GE(std::min({clipped.rgb.r, clipped.rgb.g, clipped.rgb.b}), 0.0);
  EXPECT_FALSE(clip_radiance_rgb(xyz_to_radiance_rgb({1, 1, 1})).clipped);
}

}  // namespace
}  // namespace clearsky::api
