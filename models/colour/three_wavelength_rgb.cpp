// k_r, k_g, k_b by numerical integration at 1 nm over 360..830 nm.
#include "models/colour/three_wavelength_rgb.h"

#include <cmath>

#include "models/atmosphere/solar_spectrum.h"
#include "models/colour/daylight_spectrum.h"
#include "models/spectral/reference_spectra.h"

namespace clearsky {

ThreeWavelengthRgb::ThreeWavelengthRgb(std::array<double, 3> wavelengths_nm, double alpha)
    : wavelengths_nm_(wavelengths_nm), alpha_(alpha) {
  const auto& ref = ReferenceSpectra::get();
  const auto& solar = ref.astm_g173_extraterrestrial;
  std::array<double, 3> integral{0.0, 0.0, 0.0};
  constexpr double kStepNm = 1.0;
  for (double l = 360.0; l <= 830.0 + 1e-9; l += kStepNm) {
    const double w = (l == 360.0 || l > 830.0 - 1e-9) ? 0.5 * kStepNm : kStepNm;  // trapezoid
    const Xyz cmf{ref.cie_x_bar.at(l, OutOfRange::zero), ref.cie_y_bar.at(l, OutOfRange::zero),
                  ref.cie_z_bar.at(l, OutOfRange::zero)};
    const LinearSrgb c = xyz_to_linear_srgb(cmf);
    const double s = solar.at(l, OutOfRange::error) * std::pow(l, -alpha_) * w;
    integral[0] += c.r * s;
    integral[1] += c.g * s;
    integral[2] += c.b * s;
  }
  for (int c = 0; c < 3; ++c) {
    const double lc = wavelengths_nm_[c];
    k_[c] = integral[c] / (solar_spectrum_at_point_nm(lc) * std::pow(lc, -alpha_));
  }
}

WavelengthGrid ThreeWavelengthRgb::grid() const {
  return WavelengthGrid::points({wavelengths_nm_[2], wavelengths_nm_[1], wavelengths_nm_[0]});
}

LinearSrgb ThreeWavelengthRgb::rgb(double red, double green, double blue) const {
  return {k_[0] * red, k_[1] * green, k_[2] * blue};
}

LinearSrgb ThreeWavelengthRgb::rgb(const Spectrum& on_grid) const {
  return rgb(on_grid[2], on_grid[1], on_grid[0]);
}

Spectrum ThreeWavelengthRgb::reconstruct_spectrum(const Spectrum& on_grid,
                                                  const WavelengthGrid& target) const {
  return daylight_spectrum(xyz_to_xyy(linear_srgb_to_xyz(rgb(on_grid))), target);
}

}  // namespace clearsky
