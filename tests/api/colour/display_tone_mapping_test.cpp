// The PNG skydome's display mapping (api/colour/display_tone_mapping.h): exposure in EV100, the
// two tone curves and the IEC 61966-2-1 encoding, at values worked by hand.
#include "api/colour/display_tone_mapping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace clearsky::api {
namespace {

// The radiometric value (Y scale, W/(m2.sr)) whose luminance is the saturation luminance of
// EV100 ev, 1.2 x 2^ev cd/m2: it maps to 1 before the tone curve.
double saturating_value(double ev) { return 1.2 * std::exp2(ev) / 683.0; }

TEST(DisplayToneMapping, ReinhardAtTheSaturationLuminanceIsHalfThenSrgbEncoded) {
  const DisplayToneMapping mapping(10.0, ToneCurve::reinhard);
  // x = 1 -> 1 / (1 + 1) = 0.5 -> 1.055 x 0.5^(1/2.4) - 0.055 = 0.7354 -> 187.5 -> 188.
  EXPECT_EQ(mapping.display_component(saturating_value(10.0)), 188);
}

TEST(DisplayToneMapping, AcesFitAtTheSaturationLuminance) {
  const DisplayToneMapping mapping(10.0, ToneCurve::aces);
  // x = 1 -> (2.51 + 0.03) / (2.43 + 0.59 + 0.14) = 0.80380 -> 0.90823 -> 231.6 -> 232.
  EXPECT_EQ(mapping.display_component(saturating_value(10.0)), 232);
  EXPECT_EQ(mapping.display_component(1e9), 255);  // clamped to 1
}

TEST(DisplayToneMapping, BlackNegativeAndNanAreBlack) {
  const DisplayToneMapping mapping(12.0, ToneCurve::aces);
  EXPECT_EQ(mapping.display_component(0.0), 0);
  EXPECT_EQ(mapping.display_component(-1.0), 0);
  EXPECT_EQ(mapping.display_component(std::nan("")), 0);
}

TEST(DisplayToneMapping, LinearSegmentOfTheSrgbCurve) {
  // Reinhard x / (1 + x) = 0.001 (below 0.0031308) -> 12.92 x 0.001 = 0.01292 -> 3.29 -> 3.
  const DisplayToneMapping mapping(8.0, ToneCurve::reinhard);
  const double x = 0.001 / (1.0 - 0.001);
  EXPECT_EQ(mapping.display_component(x * saturating_value(8.0)), 3);
}

TEST(DisplayToneMapping, AHigherExposureValueIsDarker) {
  const double sky = 5.0;  // W/(m2.sr), about 3400 cd/m2
  int previous = 256;
  for (double ev = 8.0; ev <= 18.0; ev += 2.0) {
    const int value = DisplayToneMapping(ev, ToneCurve::aces).display_component(sky);
    EXPECT_LT(value, previous) << ev;
    previous = value;
  }
}

TEST(DisplayToneMapping, ExposureOutsideItsRangeAndUnknownCurvesAreRefused) {
  EXPECT_THROW(DisplayToneMapping(24.5, ToneCurve::aces), std::invalid_argument);
  EXPECT_THROW(DisplayToneMapping(-10.5, ToneCurve::aces), std::invalid_argument);
  EXPECT_THROW(DisplayToneMapping(std::nan(""), ToneCurve::aces), std::invalid_argument);
  EXPECT_EQ(tone_curve_named("reinhard"), ToneCurve::reinhard);
  EXPECT_THROW(tone_curve_named("filmic"), std::invalid_argument);
}

}  // namespace
}  // namespace clearsky::api
