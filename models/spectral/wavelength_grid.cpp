// WavelengthGrid: construction checks and integration weights.
#include "models/spectral/wavelength_grid.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "models/core/invalid_input.h"

namespace clearsky {

WavelengthGrid WavelengthGrid::paper_bins() {
  // Every default ModelConfig starts from this grid (one per request): made once, copied after.
  static const WavelengthGrid grid = bins(360.0, 11.75, 40);
  return grid;
}

WavelengthGrid WavelengthGrid::bins(double start_nm, double width_nm, std::size_t count) {
  if (!(std::isfinite(start_nm) && start_nm > 0.0)) {
    throw InvalidInput("wavelengths", "bins: start must be a finite positive wavelength");
  }
  if (!(std::isfinite(width_nm) && width_nm > 0.0)) {
    throw InvalidInput("wavelengths", "bins: width must be finite and positive");
  }
  if (count == 0 || count > 100000) {
    throw InvalidInput("wavelengths", "bins: count must be between 1 and 100000");
  }
  std::vector<double> nm(count);
  for (std::size_t i = 0; i < count; ++i) nm[i] = start_nm + width_nm * static_cast<double>(i);
  return WavelengthGrid(Kind::bins, std::move(nm), width_nm);
}

WavelengthGrid WavelengthGrid::points(std::vector<double> wavelengths_nm) {
  if (wavelengths_nm.empty() || wavelengths_nm.size() > 100000) {
    throw InvalidInput("wavelengths", "between 1 and 100000 values are required");
  }
  for (std::size_t i = 0; i < wavelengths_nm.size(); ++i) {
    const double w = wavelengths_nm[i];
    if (!(std::isfinite(w) && w > 0.0)) {
      throw InvalidInput("wavelengths", "each must be a finite positive number of nm");
    }
    if (i > 0 && !(w > wavelengths_nm[i - 1])) {
      throw InvalidInput("wavelengths", "must be strictly increasing");
    }
  }
  return WavelengthGrid(Kind::points, std::move(wavelengths_nm), 0.0);
}

double WavelengthGrid::lower_edge_nm(std::size_t i) const {
  if (kind_ == Kind::bins) return nm_[i];
  return i == 0 ? nm_[0] : 0.5 * (nm_[i - 1] + nm_[i]);
}

double WavelengthGrid::upper_edge_nm(std::size_t i) const {
  if (kind_ == Kind::bins) return nm_[i] + bin_width_nm_;
  return i + 1 == nm_.size() ? nm_[i] : 0.5 * (nm_[i] + nm_[i + 1]);
}

double WavelengthGrid::integration_weight_nm(std::size_t i) const {
  return upper_edge_nm(i) - lower_edge_nm(i);
}

std::size_t WavelengthGrid::index_of(double wavelength_nm) const {
  for (std::size_t i = 0; i < nm_.size(); ++i) {
    if (std::abs(nm_[i] - wavelength_nm) <= 1e-9) return i;
  }
  return nm_.size();
}

std::string WavelengthGrid::canonical_string() const {
  std::ostringstream out;
  out.precision(17);
  if (kind_ == Kind::bins) {
    out << "bins:" << nm_.front() << ',' << bin_width_nm_ << ',' << nm_.size();
  } else {
    out << "points:";
    for (std::size_t i = 0; i < nm_.size(); ++i) out << (i ? "," : "") << nm_[i];
  }
  return out.str();
}

}  // namespace clearsky
