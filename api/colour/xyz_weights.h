// CIE 1931 XYZ of a spectrum on a fixed grid as three dot products: the weights are the XYZ
// of each unit sample (spectrum_to_xyz of e_i, models/colour), computed once per grid so that
// batches and skydome pixels do not resample the colour matching functions per sample.
// interpolating() instead integrates the colour matching functions against the spectrum
// interpolated between the samples, for short grids (api/colour/colour_wavelengths.h).
// Immutable after construction; thread-safe.
#pragma once

#include <span>
#include <vector>

#include "models/colour/colour_spaces.h"
#include "models/spectral/wavelength_grid.h"

namespace clearsky::api {

class XyzWeights {
 public:
  explicit XyzWeights(const WavelengthGrid& grid);
  // Weights for a spectrum known at the nodes of grid (increasing wavelengths) and taken as
  // linear between them and constant beyond the first and last: w_i = integral of
  // phi_i(lambda) x_bar(lambda) d lambda over the colour matching functions' table (360 to
  // 830 nm, CIE 15:2004 table T.4, as in models/colour/colour_spaces.h), phi_i the piecewise
  // linear "hat" that is 1 at node i and 0 at the other nodes (the first and last held at 1
  // outward). The XYZ is then exact for any spectrum of that shape, where point-sampling the
  // functions at a 40 nm spacing would miss their peaks.
  static XyzWeights interpolating(const WavelengthGrid& grid);
  Xyz xyz(std::span<const double> spectrum) const;
  // xyz() of count spectra of `length` values each, spectrum j at spectra + j * length (the
  // rows of a SpectralBatch), into out[j]. Each is bit for bit xyz() of that spectrum: the same
  // products added in the same order from 0, so that a skydome's colours are those of the
  // per-pixel path. On processors with AVX2, four spectra per instruction (their values
  // transposed four wavelengths at a time); AVX2 without FMA, whose fused multiply-adds would
  // round differently from the products and sums of xyz().
  void xyz_of_rows(const double* spectra, std::size_t length, std::size_t count, Xyz* out) const;
  // 683 Y: cd/m2 for a radiance.
  double luminance(std::span<const double> spectrum) const {
    return kMaxLuminousEfficacy * xyz(spectrum).y;
  }

 private:
  XyzWeights() = default;
  std::vector<double> x_, y_, z_;
};

}  // namespace clearsky::api
