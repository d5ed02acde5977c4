// The paper's 3-wavelength colour method (section "Spectrum sampling", eq. "rgb"):
//   [c_r, c_g, c_b] ~ [k_r L(lambda_r), k_g L(lambda_g), k_b L(lambda_b)],
//   k_c = integral over [360, 830] nm of c~(lambda) S(lambda) lambda^-alpha d lambda
//         / (S(lambda_c) lambda_c^-alpha),
// where c~ are the linear sRGB colour matching functions (sRGB matrix times x_bar, y_bar,
// z_bar), S the extraterrestrial solar spectrum, alpha = 3 and lambda_r,g,b = 680, 550, 440 nm.
// It rests on the sky radiance near lambda_c being about L(lambda_c) S(lambda) lambda^-alpha /
// (S(lambda_c) lambda_c^-alpha). And the paper's 3-sample spectrum reconstruction: those RGB
// -> XYZ -> xyY -> CIE daylight spectrum (daylight_spectrum.h).
#pragma once

#include <array>

#include "models/colour/colour_spaces.h"
#include "models/spectral/spectrum.h"
#include "models/spectral/wavelength_grid.h"

namespace clearsky {

class ThreeWavelengthRgb {
 public:
  static constexpr std::array<double, 3> kPaperWavelengthsNm = {680.0, 550.0, 440.0};
  static constexpr double kPaperAlpha = 3.0;

  // S(lambda) is the ASTM G-173 extraterrestrial spectrum; S(lambda_c) is taken as
  // solar_spectrum_at_point_nm (atmosphere/solar_spectrum.h), the value models use at a point
  // wavelength, so that k_c cancels the solar spectrum the model put in L(lambda_c).
  explicit ThreeWavelengthRgb(std::array<double, 3> wavelengths_nm = kPaperWavelengthsNm,
                              double alpha = kPaperAlpha);

  // The wavelengths to compute L at, as a point grid in increasing order (440, 550, 680).
  WavelengthGrid grid() const;
  const std::array<double, 3>& k() const { return k_; }

  // L at lambda_r, lambda_g, lambda_b (in that order: red, green, blue).
  LinearSrgb rgb(double radiance_red, double radiance_green, double radiance_blue) const;
  // Same, from a spectrum computed on grid().
  LinearSrgb rgb(const Spectrum& on_grid) const;
  // The paper's reconstruction of a full spectrum on target from the 3 samples on grid().
  Spectrum reconstruct_spectrum(const Spectrum& on_grid, const WavelengthGrid& target) const;

 private:
  std::array<double, 3> wavelengths_nm_;
  double alpha_;
  std::array<double, 3> k_{};
};

}  // namespace clearsky
