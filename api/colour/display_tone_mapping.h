// From linear sRGB radiance (the RGB skydome's values: Y in W/(m2.sr), docs/http-api.md "RGB")
// to an 8-bit sRGB display value, for the PNG skydome (GET /v1/skydome?format=png):
//
// 1. exposure: the photometric exposure of a camera set to EV100 (ISO 100), the luminance that
//    saturates the sensor being 1.2 x 2^EV100 cd/m2 (the saturation-based sensitivity of
//    ISO 12232:2006; Lagarde and de Rousiers 2014, "Moving Frostbite to Physically Based
//    Rendering", section 5.1): scaled = 683 lm/W x value / (1.2 x 2^EV100);
// 2. a tone curve, per component, mapping [0, inf) into [0, 1]:
//    - aces: Narkowicz 2016, "ACES Filmic Tone Mapping Curve", the fit
//      x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14) to the ACES reference rendering transform,
//      clamped to [0, 1];
//    - reinhard: Reinhard, Stark, Shirley and Ferwerda 2002, "Photographic Tone Reproduction for
//      Digital Images", equation 3: x / (1 + x);
// 3. the sRGB transfer function of IEC 61966-2-1 (12.92 x below 0.0031308, else
//    1.055 x^(1/2.4) - 0.055), rounded to the nearest of 0..255.
//
// | parameter | unit   | default | range       | meaning                                   |
// |-----------|--------|---------|-------------|-------------------------------------------|
// | exposure  | EV100  | 14      | [-10, 24]   | saturation luminance 1.2 x 2^EV100 cd/m2  |
// | tone_map  | -      | aces    | aces, reinhard | the tone curve of step 2               |
//
// EV100 14 saturates at 19661 cd/m2: a clear day's sky (2000 to 10000 cd/m2 away from the sun)
// lands in the middle of the curve and the aureole rolls off in its shoulder. Thread-safety: immutable after construction.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "models/colour/colour_spaces.h"

namespace clearsky::api {

enum class ToneCurve { aces, reinhard };

inline constexpr double kDefaultExposureEv100 = 14.0;
inline constexpr double kMinExposureEv100 = -10.0;
inline constexpr double kMaxExposureEv100 = 24.0;

// The tone curve named by a request ("aces", "reinhard"); throws std::invalid_argument otherwise.
ToneCurve tone_curve_named(const std::string& name);

class DisplayToneMapping {
 public:
  DisplayToneMapping(double exposure_ev100, ToneCurve curve);
  // The 8-bit sRGB display value of each component of a linear sRGB radiance.
  std::array<std::uint8_t, 3> display(const LinearSrgb& radiance) const;
  // One component: a radiometric value (W/(m2.sr) scale) -> 0..255.
  std::uint8_t display_component(double value) const;

 private:
  double scale_;  // 683 lm/W / (1.2 x 2^EV100)
  ToneCurve curve_;
};

}  // namespace clearsky::api
