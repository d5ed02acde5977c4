// CIE 1931 XYZ of a spectrum on a fixed grid as three dot products: the weights are the XYZ
// of each unit sample (spectrum_to_xyz of e_i, models/colour), computed once per grid so that
// batches and skydome pixels do not resample the colour matching functions per sample.
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
  Xyz xyz(std::span<const double> spectrum) const;
  // 683 Y: cd/m2 for a radiance.
  double luminance(std::span<const double> spectrum) const {
    return kMaxLuminousEfficacy * xyz(spectrum).y;
  }

 private:
  std::vector<double> x_, y_, z_;
};

}  // namespace clearsky::api
