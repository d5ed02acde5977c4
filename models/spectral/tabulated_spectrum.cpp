// TabulatedSpectrum: linear interpolation, exact integrals of the piecewise-linear function,
// and the text table reader.
#include "models/spectral/tabulated_spectrum.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace clearsky {

TabulatedSpectrum::TabulatedSpectrum(std::vector<double> wavelengths_nm, std::vector<double> values)
    : nm_(std::move(wavelengths_nm)), v_(std::move(values)) {
  if (nm_.empty() || nm_.size() != v_.size()) {
    throw std::invalid_argument(
        "tabulated spectrum: wavelengths and values must be non-empty and of equal length");
  }
  for (std::size_t i = 0; i < nm_.size(); ++i) {
    if (!std::isfinite(nm_[i]) || !std::isfinite(v_[i])) {
      throw std::invalid_argument("tabulated spectrum: non-finite entry");
    }
    if (i > 0 && !(nm_[i] > nm_[i - 1])) {
      throw std::invalid_argument("tabulated spectrum: wavelengths must be strictly increasing");
    }
  }
}

namespace {

void check_range(const TabulatedSpectrum& s, double lo, double hi) {
  if (lo < s.min_nm() - 1e-9 || hi > s.max_nm() + 1e-9) {
    std::ostringstream msg;
    msg << "wavelength range [" << lo << ", " << hi << "] nm is outside the table's [" << s.min_nm()
        << ", " << s.max_nm() << "] nm";
    throw std::out_of_range(msg.str());
  }
}

}  // namespace

double TabulatedSpectrum::at(double wavelength_nm, OutOfRange policy) const {
  if (!std::isfinite(wavelength_nm)) throw std::invalid_argument("wavelength is not finite");
  if (wavelength_nm < nm_.front() || wavelength_nm > nm_.back()) {
    switch (policy) {
      case OutOfRange::zero:
        return 0.0;
      case OutOfRange::hold_end_values:
        return wavelength_nm < nm_.front() ? v_.front() : v_.back();
      case OutOfRange::error:
        check_range(*this, wavelength_nm, wavelength_nm);
    }
  }
  if (nm_.size() == 1) return v_.front();
  const auto it = std::upper_bound(nm_.begin(), nm_.end(), wavelength_nm);
  const std::size_t i1 =
      std::min<std::size_t>(static_cast<std::size_t>(it - nm_.begin()), nm_.size() - 1);
  const std::size_t i0 = i1 - 1;
  // Halved before the differences, so that wavelengths of opposite sign near the largest
  // double do not overflow the span to infinity (t would then be 0 at the upper node); for any
  // two finite doubles the halves' difference is finite, and the halving is exact.
  const double t = (0.5 * wavelength_nm - 0.5 * nm_[i0]) / (0.5 * nm_[i1] - 0.5 * nm_[i0]);
  // The convex combination, not v0 + t (v1 - v0): the difference of two finite values of
  // opposite sign near the largest double overflows, and 0 * inf would be NaN at a node.
  return (1.0 - t) * v_[i0] + t * v_[i1];
}

double TabulatedSpectrum::integral_inside(double lo, double hi) const {
  // Sum of trapezoids of the piecewise-linear function over [lo, hi] within the table.
  double sum = 0.0;
  double x0 = lo;
  double y0 = at(lo, OutOfRange::hold_end_values);
  auto it = std::upper_bound(nm_.begin(), nm_.end(), lo);
  for (; it != nm_.end() && *it < hi; ++it) {
    const double x1 = *it;
    const double y1 = v_[static_cast<std::size_t>(it - nm_.begin())];
    sum += 0.5 * (y0 + y1) * (x1 - x0);
    x0 = x1;
    y0 = y1;
  }
  sum += 0.5 * (y0 + at(hi, OutOfRange::hold_end_values)) * (hi - x0);
  return sum;
}

double TabulatedSpectrum::integral(double lo, double hi, OutOfRange policy) const {
  if (!(std::isfinite(lo) && std::isfinite(hi) && hi >= lo)) {
    throw std::invalid_argument("integral: need finite lo <= hi");
  }
  if (policy == OutOfRange::error) check_range(*this, lo, hi);
  const double in_lo = std::clamp(lo, nm_.front(), nm_.back());
  const double in_hi = std::clamp(hi, nm_.front(), nm_.back());
  double sum = in_hi > in_lo ? integral_inside(in_lo, in_hi) : 0.0;
  if (policy == OutOfRange::hold_end_values) {
    if (lo < nm_.front()) sum += v_.front() * (std::min(hi, nm_.front()) - lo);
    if (hi > nm_.back()) sum += v_.back() * (hi - std::max(lo, nm_.back()));
  }
  return sum;
}

double TabulatedSpectrum::bin_average(double lo, double hi, OutOfRange policy) const {
  if (!(hi > lo)) return at(lo, policy);
  return integral(lo, hi, policy) / (hi - lo);
}

Spectrum TabulatedSpectrum::resample(const WavelengthGrid& grid, Resampling how,
                                     OutOfRange policy) const {
  Spectrum out(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    out[i] = how == Resampling::point
                 ? at(grid[i], policy)
                 : bin_average(grid.lower_edge_nm(i), grid.upper_edge_nm(i), policy);
  }
  return out;
}

TabulatedSpectrum TabulatedSpectrum::scaled(double factor) const {
  std::vector<double> v = v_;
  for (double& x : v) x *= factor;
  return TabulatedSpectrum(nm_, std::move(v));
}

std::size_t NumericTable::column_index(std::string_view name) const {
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (columns[i] == name) return i;
  }
  throw std::out_of_range("table has no column '" + std::string(name) + "'");
}

std::vector<double> NumericTable::column(std::size_t index) const {
  std::vector<double> out;
  out.reserve(rows.size());
  for (const auto& row : rows) out.push_back(row.at(index));
  return out;
}

TabulatedSpectrum NumericTable::spectrum(std::size_t x_column, std::size_t y_column) const {
  return TabulatedSpectrum(column(x_column), column(y_column));
}

namespace {

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() &&
           (line[i] == ',' || line[i] == ' ' || line[i] == '\t' || line[i] == '\r'))
      ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ',' && line[j] != ' ' && line[j] != '\t' &&
           line[j] != '\r')
      ++j;
    if (j > i) fields.push_back(line.substr(i, j - i));
    i = j;
  }
  return fields;
}

bool parse_double(std::string_view text, double& value) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end && std::isfinite(value);
}

}  // namespace

NumericTable read_numeric_table(std::istream& in, const std::string& source) {
  NumericTable table;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const auto fields = split_fields(line);
    if (fields.empty() || fields.front().starts_with("#")) continue;
    std::vector<double> row;
    row.reserve(fields.size());
    bool numeric = true;
    for (auto field : fields) {
      double v = 0.0;
      if (!parse_double(field, v)) {
        numeric = false;
        break;
      }
      row.push_back(v);
    }
    if (!numeric) {
      if (table.rows.empty() && table.columns.empty()) {
        for (auto field : fields) table.columns.emplace_back(field);
        continue;
      }
      throw std::runtime_error(source + ":" + std::to_string(line_number) + ": malformed row '" +
                               line + "'");
    }
    const std::size_t expected = !table.columns.empty() ? table.columns.size()
                                 : table.rows.empty()   ? row.size()
                                                        : table.rows.front().size();
    if (row.size() != expected) {
      throw std::runtime_error(source + ":" + std::to_string(line_number) + ": expected " +
                               std::to_string(expected) + " fields, found " +
                               std::to_string(row.size()));
    }
    table.rows.push_back(std::move(row));
  }
  if (table.rows.empty()) throw std::runtime_error(source + ": no data rows");
  return table;
}

}  // namespace clearsky
