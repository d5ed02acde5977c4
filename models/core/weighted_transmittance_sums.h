// The two single-scattering integrals of a view ray (Rayleigh and Mie: sums over the ray's
// samples of weight x transmittance on every wavelength), gathered sample by sample and added
// in chunks by one vector pass of add_weighted_transmittances (fast_exp.h). Collecting the
// samples first lets the 40 exponentials of a sample run in the same vector loop as their
// clamps and the two sums, once per chunk instead of two kernel calls per sample; the chunk
// lives on the stack, so a ray of any sample count allocates nothing. The sums equal those of
// transmittance_from_lengths and add_scaled_pair called per sample, bit for bit.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

#include "models/core/fast_exp.h"

namespace clearsky {

class WeightedTransmittanceSums {
 public:
  // Zeroes sum_a and sum_b (n values each); beta_* are the extinction coefficients the
  // transmittances exp(-(beta_rayleigh L_R + beta_mie L_M)) use. The arrays must outlive this.
  WeightedTransmittanceSums(std::size_t n, const double* beta_rayleigh_per_m,
                            const double* beta_mie_per_m, double* sum_a, double* sum_b)
      : n_(n),
        beta_rayleigh_(beta_rayleigh_per_m),
        beta_mie_(beta_mie_per_m),
        sum_a_(sum_a),
        sum_b_(sum_b) {
    std::fill_n(sum_a, n, 0.0);
    std::fill_n(sum_b, n, 0.0);
  }

  // A sample: its optical lengths from the observer through it to the sun, and its weights.
  void add(double rayleigh_m, double mie_m, double weight_a, double weight_b) {
    if (count_ == kChunk) flush();
    rayleigh_m_[count_] = rayleigh_m;
    mie_m_[count_] = mie_m;
    weight_a_[count_] = weight_a;
    weight_b_[count_] = weight_b;
    ++count_;
  }

  // Adds the samples gathered so far to the sums; call before reading them.
  void flush() {
    add_weighted_transmittances(
        n_, beta_rayleigh_, beta_mie_,
        {rayleigh_m_.data(), mie_m_.data(), weight_a_.data(), weight_b_.data(), count_}, sum_a_,
        sum_b_);
    count_ = 0;
  }

 private:
  // Nishita93's rays have about 65 samples at the paper's 64 spheres, O'Neal's 4.
  static constexpr std::size_t kChunk = 32;
  std::size_t n_;
  const double* beta_rayleigh_;
  const double* beta_mie_;
  double* sum_a_;
  double* sum_b_;
  std::size_t count_ = 0;
  std::array<double, kChunk> rayleigh_m_, mie_m_, weight_a_, weight_b_;
};

}  // namespace clearsky
