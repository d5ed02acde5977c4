// The gamut mapping of linear sRGB (api/colour/srgb_gamut.h): negative components become 0 and
// are reported; everything else, above 1 included, is kept as it is.
#include "api/colour/srgb_gamut.h"

#include <gtest/gtest.h>

#include <cmath>

namespace clearsky::api {
namespace {

TEST(SrgbGamut, NegativeComponentsAreClippedAndReported) {
  const GamutMappedSrgb mapped = clip_to_srgb_gamut({2.5, -0.25, 0.125});
  EXPECT_TRUE(mapped.clipped);
  EXPECT_EQ(mapped.rgb.r, 2.5);
  EXPECT_EQ(mapped.rgb.g, 0.0);
  EXPECT_EQ(mapped.rgb.b, 0.125);
  const GamutMappedSrgb all = clip_to_srgb_gamut({-1e-12, -3.0, -0.5});
  EXPECT_TRUE(all.clipped);
  EXPECT_EQ(all.rgb.r, 0.0);
  EXPECT_EQ(all.rgb.g, 0.0);
  EXPECT_EQ(all.rgb.b, 0.0);
}

TEST(SrgbGamut, ColoursInTheGamutAreKept) {
  const GamutMappedSrgb mapped = clip_to_srgb_gamut({0.0, 12.0, 0.5});
  EXPECT_FALSE(mapped.clipped);
  EXPECT_EQ(mapped.rgb.r, 0.0);
  EXPECT_EQ(mapped.rgb.g, 12.0);
  EXPECT_EQ(mapped.rgb.b, 0.5);
  // -0 is the same value as 0: not clipped, and sent without its sign.
  const GamutMappedSrgb zero = clip_to_srgb_gamut({-0.0, 1.0, 1.0});
  EXPECT_FALSE(zero.clipped);
  EXPECT_FALSE(std::signbit(zero.rgb.r));
}

}  // namespace
}  // namespace clearsky::api
