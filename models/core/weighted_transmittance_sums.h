// The two single-scattering integrals of a view ray (Rayleigh and Mie: sums over the ray's
// samples of weight x transmittance on every wavelength), gathered sample by sample and added
// in chunks by one vector pass of the transmittance kernel (fast_exp.h). Collecting the
// samples first lets the 40 exponentials of a sample run in the same vector loop as their
// clamps and the two sums, once per chunk instead of two kernel calls per sample; the chunk
// lives on the stack, so a ray of any sample count allocates nothing.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

#include "models/core/fast_exp.h"

namespace clearsky {

// Which exponential the sums' transmittances use.
enum class TransmittanceKernel {
  // add_weighted_transmittances_float: each transmittance within 1e-7 relative of std::exp,
  // about half the instructions; what the models answer with.
  float_polynomial,
  // add_weighted_transmittances: within 2 ulp of std::exp, bit for bit
  // transmittance_from_lengths then add_scaled_pair per sample; the exact formula the tests
  // hold the float kernel's radiances to.
  double_polynomial,
};

class WeightedTransmittanceSums {
 public:
  // Zeroes sum_a and sum_b (n values each); beta_* are the extinction coefficients the
  // transmittances exp(-(beta_rayleigh L_R + beta_mie L_M)) use. The arrays must outlive this.
  WeightedTransmittanceSums(std::size_t n, const double* beta_rayleigh_per_m,
                            const double* beta_mie_per_m, double* sum_a, double* sum_b,
                            TransmittanceKernel kernel = TransmittanceKernel::float_polynomial)
      : n_(n),
        beta_rayleigh_(beta_rayleigh_per_m),
        beta_mie_(beta_mie_per_m),
        sum_a_(sum_a),
        sum_b_(sum_b),
        kernel_(kernel) {
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
    const WeightedSamples samples{rayleigh_m_.data(), mie_m_.data(), weight_a_.data(),
                                  weight_b_.data(), count_};
    if (kernel_ == TransmittanceKernel::float_polynomial) {
      add_weighted_transmittances_float(n_, beta_rayleigh_, beta_mie_, samples, sum_a_, sum_b_);
    } else {
      add_weighted_transmittances(n_, beta_rayleigh_, beta_mie_, samples, sum_a_, sum_b_);
    }
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
  TransmittanceKernel kernel_;
  std::size_t count_ = 0;
  std::array<double, kChunk> rayleigh_m_, mie_m_, weight_a_, weight_b_;
};

}  // namespace clearsky
