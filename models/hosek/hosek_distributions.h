// The Hosek-Wilkie distribution (Hosek and Wilkie 2012, eq. 9; hosek::distribution() of
// hosek_functions.h) of every cooked configuration of one sun at one view, as vector loops over
// the coefficients stored structure of arrays (one array per coefficient A..I), so that one
// view's 61 distributions of the study's 40-wavelength evaluation (models/hosek/README.md) are
// computed a vector of them at a time, the exponentials in one pass (fast_exp.h) and the
// anisotropy term's square root and division vectorised too (hosek_distributions.cpp).
// Each value is hosek::distribution() with its exponentials from exp_in_place(): the same
// operations in the same order, bit for bit on every processor
// (tests/models/hosek/hosek_distributions_test.cpp).
// Immutable after the configurations are added; evaluate() is const and thread-safe.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "models/hosek/hosek_functions.h"

namespace clearsky::hosek {

class Distributions {
 public:
  // Appends one configuration's coefficients; returns its index.
  std::uint32_t add(const Coefficients& c);
  std::size_t size() const { return coefficient_[0].size(); }
  std::size_t memory_bytes() const { return size() * sizeof(double) * (kCoefficientCount + 2); }
  // f[t] = hosek::distribution(configuration t, v) for every t < size() (without L_M), with
  // exp_in_place()'s exponentials. exponents: scratch of 2 size() doubles.
  void evaluate(const ViewTerms& v, double* exponents, double* f) const;

 private:
  std::array<std::vector<double>, kCoefficientCount> coefficient_;
  // The anisotropy term's view-independent parts, 1 + g^2 and 2 g (g = H, index 8), as
  // distribution() rounds them before it subtracts 2 g cos(gamma).
  std::vector<double> mie_constant_, mie_slope_;
};

}  // namespace clearsky::hosek
