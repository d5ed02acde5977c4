// The wavelengths a computation runs at. Two kinds, kept explicit because they integrate
// differently:
//  - bins: sample i stands for [start + i w, start + (i + 1) w) and is integrated as that bin
//    (the 2016 study's grid: 40 bins of 11.75 nm from 360 nm,
//    docs/architecture.md "Conventions and units");
//  - points: arbitrary increasing wavelengths, integrated with the trapezoid rule.
// Wavelengths in nanometres. Immutable value type; thread-safe.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace clearsky {

class WavelengthGrid {
 public:
  enum class Kind { bins, points };

  // The paper's grid: 40 bins, 11.75 nm wide, starting at 360 nm (360 ... 818.25 nm).
  static WavelengthGrid paper_bins();
  // count bins of width_nm starting at start_nm; throws std::invalid_argument when invalid.
  static WavelengthGrid bins(double start_nm, double width_nm, std::size_t count);
  // Strictly increasing, finite, positive wavelengths; throws std::invalid_argument otherwise.
  static WavelengthGrid points(std::vector<double> wavelengths_nm);

  Kind kind() const { return kind_; }
  std::size_t size() const { return nm_.size(); }
  double operator[](std::size_t i) const { return nm_[i]; }
  const std::vector<double>& nanometres() const { return nm_; }
  // Width of each bin (0 for a point grid).
  double bin_width_nm() const { return bin_width_nm_; }

  // Weight of sample i in an integral over wavelength, in nm: the bin width for bins, the
  // trapezoid weight for points (half the neighbouring spacings; 0 for a single point).
  double integration_weight_nm(std::size_t i) const;
  // The interval a sample stands for: the bin, or the midpoints to its neighbours.
  double lower_edge_nm(std::size_t i) const;
  double upper_edge_nm(std::size_t i) const;

  // Index of the sample equal to wavelength_nm within 1e-9 nm, or size() when none is.
  std::size_t index_of(double wavelength_nm) const;

  // A canonical text form for cache keys: "bins:360,11.75,40" or "points:440,550,680".
  std::string canonical_string() const;

  bool operator==(const WavelengthGrid& other) const = default;

 private:
  WavelengthGrid(Kind kind, std::vector<double> nm, double bin_width_nm)
      : kind_(kind), nm_(std::move(nm)), bin_width_nm_(bin_width_nm) {}

  Kind kind_;
  std::vector<double> nm_;
  double bin_width_nm_;
};

}  // namespace clearsky
