// Colour conversions; matrices from IEC 61966-2-1 (sRGB, D65).
#include "models/colour/colour_spaces.h"

#include "models/spectral/reference_spectra.h"

namespace clearsky {

namespace {

constexpr double kD65x = 0.3127, kD65y = 0.3290;

// Colour matching functions point-sampled on a grid, weighted by the integration weights.
struct WeightedCmf {
  Spectrum x, y, z;
};

WeightedCmf weighted_cmf(const WavelengthGrid& grid) {
  const auto& ref = ReferenceSpectra::get();
  WeightedCmf w{ref.cie_x_bar.resample(grid, Resampling::point, OutOfRange::zero),
                ref.cie_y_bar.resample(grid, Resampling::point, OutOfRange::zero),
                ref.cie_z_bar.resample(grid, Resampling::point, OutOfRange::zero)};
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const double dl = grid.integration_weight_nm(i);
    w.x[i] *= dl;
    w.y[i] *= dl;
    w.z[i] *= dl;
  }
  return w;
}

}  // namespace

Xyz spectrum_to_xyz(const Spectrum& spectrum, const WavelengthGrid& grid) {
  const WeightedCmf w = weighted_cmf(grid);
  Xyz out;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    out.x += w.x[i] * spectrum[i];
    out.y += w.y[i] * spectrum[i];
    out.z += w.z[i] * spectrum[i];
  }
  return out;
}

double spectrum_to_luminance(const Spectrum& spectrum, const WavelengthGrid& grid) {
  return kMaxLuminousEfficacy * spectrum_to_xyz(spectrum, grid).y;
}

LinearSrgb xyz_to_linear_srgb(const Xyz& c) {
  return {3.2404542 * c.x - 1.5371385 * c.y - 0.4985314 * c.z,
          -0.9692660 * c.x + 1.8760108 * c.y + 0.0415560 * c.z,
          0.0556434 * c.x - 0.2040259 * c.y + 1.0572252 * c.z};
}

Xyz linear_srgb_to_xyz(const LinearSrgb& c) {
  return {0.4124564 * c.r + 0.3575761 * c.g + 0.1804375 * c.b,
          0.2126729 * c.r + 0.7151522 * c.g + 0.0721750 * c.b,
          0.0193339 * c.r + 0.1191920 * c.g + 0.9503041 * c.b};
}

Xyy xyz_to_xyy(const Xyz& c) {
  const double sum = c.x + c.y + c.z;
  if (!(sum > 0.0)) return {kD65x, kD65y, 0.0};
  return {c.x / sum, c.y / sum, c.y};
}

Xyz xyy_to_xyz(const Xyy& c) {
  if (!(c.chroma_y > 0.0)) return {0.0, 0.0, 0.0};
  const double scale = c.luminance_y / c.chroma_y;
  return {c.chroma_x * scale, c.luminance_y, (1.0 - c.chroma_x - c.chroma_y) * scale};
}

LinearSrgb spectrum_to_linear_srgb(const Spectrum& spectrum, const WavelengthGrid& grid) {
  return xyz_to_linear_srgb(spectrum_to_xyz(spectrum, grid));
}

}  // namespace clearsky
