// CIE 1931 XYZ from spectra, luminance, and the linear sRGB / xyY conversions.
// XYZ here is radiometric: X = integral of x_bar(lambda) L(lambda) d lambda, with L in
// W/(m2.sr.nm) and the colour matching functions point-sampled (linear interpolation, zero
// outside 360..830 nm); luminance in cd/m2 is 683 lm/W times Y (CIE 15:2004).
// The sRGB matrices are IEC 61966-2-1 (D65 white); "linear" means without the transfer curve.
#pragma once

#include <array>

#include "models/spectral/spectrum.h"
#include "models/spectral/wavelength_grid.h"

namespace clearsky {

inline constexpr double kMaxLuminousEfficacy = 683.0;  // lm/W

struct Xyz {
  double x = 0, y = 0, z = 0;
};
struct Xyy {
  double chroma_x = 0, chroma_y = 0, luminance_y = 0;
};
struct LinearSrgb {
  double r = 0, g = 0, b = 0;
};

// Integrates spectrum (on grid) against the CIE 1931 2-degree colour matching functions with
// the grid's integration weights.
Xyz spectrum_to_xyz(const Spectrum& spectrum, const WavelengthGrid& grid);
// 683 * Y: cd/m2 for a radiance, lx for an irradiance.
double spectrum_to_luminance(const Spectrum& spectrum, const WavelengthGrid& grid);

LinearSrgb xyz_to_linear_srgb(const Xyz& xyz);
Xyz linear_srgb_to_xyz(const LinearSrgb& rgb);
// Chromaticity of black (X+Y+Z = 0) is reported as the D65 white point, with Y = 0.
Xyy xyz_to_xyy(const Xyz& xyz);
Xyz xyy_to_xyz(const Xyy& xyy);

LinearSrgb spectrum_to_linear_srgb(const Spectrum& spectrum, const WavelengthGrid& grid);

}  // namespace clearsky
