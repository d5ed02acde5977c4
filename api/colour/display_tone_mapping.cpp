// Exposure, tone curve and sRGB encoding of the PNG skydome (display_tone_mapping.h).
#include "api/colour/display_tone_mapping.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace clearsky::api {

namespace {

// Narkowicz 2016, "ACES Filmic Tone Mapping Curve".
double aces_fitted(double x) {
  const double y = x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
  return std::clamp(y, 0.0, 1.0);
}

// Reinhard et al. 2002, "Photographic Tone Reproduction for Digital Images", equation 3.
double reinhard(double x) { return x / (1.0 + x); }

// IEC 61966-2-1: linear [0, 1] -> non-linear sRGB [0, 1].
double srgb_encode(double linear) {
  if (linear <= 0.0031308) return 12.92 * linear;
  return 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

}  // namespace

ToneCurve tone_curve_named(const std::string& name) {
  if (name == "aces") return ToneCurve::aces;
  if (name == "reinhard") return ToneCurve::reinhard;
  throw std::invalid_argument("unknown tone curve " + name);
}

DisplayToneMapping::DisplayToneMapping(double exposure_ev100, ToneCurve curve)
    : scale_(kMaxLuminousEfficacy / (1.2 * std::exp2(exposure_ev100))), curve_(curve) {
  if (!(exposure_ev100 >= kMinExposureEv100 && exposure_ev100 <= kMaxExposureEv100))
    throw std::invalid_argument("exposure outside [-10, 24] EV100");
}

std::uint8_t DisplayToneMapping::display_component(double value) const {
  // NaN and negative values (none reach here: the skydome clips to the gamut) display as black.
  const double x = value > 0.0 ? value * scale_ : 0.0;
  const double toned = curve_ == ToneCurve::aces ? aces_fitted(x) : reinhard(x);
  const double encoded = srgb_encode(std::clamp(toned, 0.0, 1.0));
  return static_cast<std::uint8_t>(std::lround(encoded * 255.0));
}

std::array<std::uint8_t, 3> DisplayToneMapping::display(const LinearSrgb& radiance) const {
  return {display_component(radiance.r), display_component(radiance.g),
          display_component(radiance.b)};
}

}  // namespace clearsky::api
