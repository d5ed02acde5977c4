// XYZ weights from unit spectra.
#include "api/colour/xyz_weights.h"

#include "models/spectral/reference_spectra.h"

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

XyzWeights XyzWeights::interpolating(const WavelengthGrid& grid) {
  XyzWeights w;
  const std::size_t n = grid.size();
  w.x_.assign(n, 0.0);
  w.y_.assign(n, 0.0);
  w.z_.assign(n, 0.0);
  if (n == 0) return w;
  const auto& ref = ReferenceSpectra::get();
  // The hat functions at lambda: the two nodes around it and their weights.
  const auto hats = [&](double nm, std::size_t& lower, double& t) {
    if (nm <= grid[0]) {
      lower = 0;
      t = 0.0;
      return;
    }
    if (nm >= grid[n - 1]) {
      lower = n - 1;
      t = 0.0;
      return;
    }
    lower = 0;
    while (lower + 1 < n && grid[lower + 1] <= nm) ++lower;
    t = lower + 1 < n ? (nm - grid[lower]) / (grid[lower + 1] - grid[lower]) : 0.0;
  };
  // Trapezoid rule at 0.25 nm over the table (tabulated every 5 nm and linear between, so the
  // integrand is piecewise quadratic: the step's error is far below the tables' 4 decimals).
  constexpr double kStepNm = 0.25;
  const double first = ref.cie_x_bar.min_nm(), last = ref.cie_x_bar.max_nm();
  const auto steps = static_cast<std::size_t>((last - first) / kStepNm + 0.5);
  for (std::size_t k = 0; k <= steps; ++k) {
    const double nm = first + kStepNm * static_cast<double>(k);
    const double dl = (k == 0 || k == steps) ? 0.5 * kStepNm : kStepNm;
    const double x = ref.cie_x_bar.at(nm, OutOfRange::zero) * dl;
    const double y = ref.cie_y_bar.at(nm, OutOfRange::zero) * dl;
    const double z = ref.cie_z_bar.at(nm, OutOfRange::zero) * dl;
    std::size_t i = 0;
    double t = 0.0;
    hats(nm, i, t);
    w.x_[i] += (1.0 - t) * x;
    w.y_[i] += (1.0 - t) * y;
    w.z_[i] += (1.0 - t) * z;
    if (t > 0.0) {
      w.x_[i + 1] += t * x;
      w.y_[i + 1] += t * y;
      w.z_[i + 1] += t * z;
    }
  }
  return w;
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
