// The spectral sums of the density J (Bruneton and Neyret 2008, Eq. 7): at one texel, the
// light of its directions is a weighted sum of the precomputed spectra (the profiles of the
// previous order at the sphere's zeniths and nu slices, and the ground's light at the
// irradiance table's columns), once with the Rayleigh-phase weights and once with the Mie-phase
// weights (density_weights.h).
//
// The two sums read the same spectra in the same order, so they are computed in one pass: each
// spectrum is loaded once and feeds both chains of multiply-adds, which overlap instead of
// running one after the other. A term whose weight is zero in one sum and not in the other is
// kept in both: a zero weight times a finite spectrum leaves a float sum exactly as it was, so
// each sum is the one sum_rows() gives over its own non-zero terms, bit for bit
// (tests/models/bruneton/density_sums_test.cpp).
#pragma once

#include <vector>

namespace clearsky::bruneton {

// The terms of one texel: spectra (rows of `stride` floats) and their two weights, in the
// order of the sums.
class DensityTerms {
 public:
  // Room for `capacity` terms; clear() keeps it.
  explicit DensityTerms(int capacity) : rows_(capacity), w_r_(capacity), w_m_(capacity) {}
  void clear() { count_ = 0; }
  // Skipped when both weights are zero, as sum_rows() lists skip theirs.
  void add(const float* row, double weight_r, double weight_m) {
    if (weight_r == 0.0 && weight_m == 0.0) return;
    rows_[count_] = row;
    w_r_[count_] = static_cast<float>(weight_r);
    w_m_[count_++] = static_cast<float>(weight_m);
  }
  int count() const { return count_; }
  // sum_r = sum of float(weight_r) x row, sum_m likewise, in the terms' order.
  void sum(int stride, float* sum_r, float* sum_m) const;
  // The same as two sum_rows() calls: the path of CPUs without AVX2, and the tests' reference.
  void sum_reference(int stride, float* sum_r, float* sum_m) const;

 private:
  std::vector<const float*> rows_;
  std::vector<float> w_r_, w_m_;
  int count_ = 0;
};

}  // namespace clearsky::bruneton
