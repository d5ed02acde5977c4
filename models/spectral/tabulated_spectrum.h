// A spectral function given as a table (wavelength_nm, value), read linearly between its
// rows. Resampling onto a WavelengthGrid is explicit about how (point value or bin average)
// and about what happens beyond the table's ends (hold the end value, zero, or an error):
// a measurement service must never make up values silently.
#pragma once

#include <istream>
#include <string>
#include <string_view>
#include <vector>

#include "models/spectral/spectrum.h"
#include "models/spectral/wavelength_grid.h"

namespace clearsky {

enum class OutOfRange { hold_end_values, zero, error };
enum class Resampling { point, bin_average };

class TabulatedSpectrum {
 public:
  TabulatedSpectrum() = default;
  // Strictly increasing finite wavelengths, finite values, same lengths (>= 1); throws
  // std::invalid_argument otherwise.
  TabulatedSpectrum(std::vector<double> wavelengths_nm, std::vector<double> values);

  double min_nm() const { return nm_.front(); }
  double max_nm() const { return nm_.back(); }
  const std::vector<double>& wavelengths_nm() const { return nm_; }
  const std::vector<double>& values() const { return v_; }

  // Linear interpolation at wavelength_nm; beyond the ends per policy (error: std::out_of_range).
  double at(double wavelength_nm, OutOfRange policy) const;
  // Mean over [lo_nm, hi_nm] of the piecewise-linear function (exact); beyond the ends per policy.
  double bin_average(double lo_nm, double hi_nm, OutOfRange policy) const;
  // Exact integral over [lo_nm, hi_nm] of the piecewise-linear function.
  double integral(double lo_nm, double hi_nm, OutOfRange policy) const;

  // Values on grid: point values at the grid wavelengths, or averages over each sample's
  // interval (WavelengthGrid::lower_edge_nm/upper_edge_nm).
  Spectrum resample(const WavelengthGrid& grid, Resampling how, OutOfRange policy) const;

  TabulatedSpectrum scaled(double factor) const;

 private:
  double integral_inside(double lo_nm, double hi_nm) const;

  std::vector<double> nm_;
  std::vector<double> v_;
};

// A numeric table read from text: '#' comment lines, an optional header line naming the
// columns, then rows of numbers separated by commas, tabs or spaces. Malformed rows are errors
// naming the line (std::runtime_error); source names the input in messages.
struct NumericTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;

  // Index of a named column; throws std::out_of_range naming it.
  std::size_t column_index(std::string_view name) const;
  std::vector<double> column(std::size_t index) const;
  // Column x against column y as a spectrum.
  TabulatedSpectrum spectrum(std::size_t x_column, std::size_t y_column) const;
};

NumericTable read_numeric_table(std::istream& in, const std::string& source);

}  // namespace clearsky
