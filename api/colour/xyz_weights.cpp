// XYZ weights from unit spectra.
#include "api/colour/xyz_weights.h"

namespace clearsky::api {

XyzWeights::XyzWeights(const WavelengthGrid& grid) {
  Spectrum unit(grid.size(), 0.0);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    unit[i] = 1.0;
    const Xyz c = spectrum_to_xyz(unit, grid);
    unit[i] = 0.0;
    x_.push_back(c.x);
    y_.push_back(c.y);
    z_.push_back(c.z);
  }
}

Xyz XyzWeights::xyz(std::span<const double> s) const {
  Xyz c;
  for (std::size_t i = 0; i < s.size() && i < x_.size(); ++i) {
    c.x += x_[i] * s[i];
    c.y += y_[i] * s[i];
    c.z += z_[i] * s[i];
  }
  return c;
}

}  // namespace clearsky::api
