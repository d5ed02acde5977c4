// The chunked single-scattering sums against the per-sample kernels they replace: with the
// double kernel the same bits, with the float kernel (the models' default) within 1e-7
// relative, for rays shorter and longer than a chunk (Nishita93's rays have about 65 samples).
#include "models/core/weighted_transmittance_sums.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "models/core/fast_exp.h"

namespace clearsky {
namespace {

struct Sums {
  std::vector<double> a, b;
};

// The chunked sums of `samples` samples with the kernel, and the per-sample kernels' sums.
void sums_of(int samples, TransmittanceKernel kernel, Sums& chunked, Sums& per_sample) {
  const std::size_t n = 40;
  std::vector<double> beta_rayleigh(n), beta_mie(n);
  for (std::size_t i = 0; i < n; ++i) {
    beta_rayleigh[i] = 3e-5 * std::pow(0.5 + 0.01 * static_cast<double>(i), -4.0) / 16.0;
    beta_mie[i] = 2e-5 + 1e-7 * static_cast<double>(i);
  }
  chunked = {std::vector<double>(n, -1.0), std::vector<double>(n, -1.0)};  // zeroed below
  per_sample = {std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  std::vector<double> t(n);
  WeightedTransmittanceSums sums(n, beta_rayleigh.data(), beta_mie.data(), chunked.a.data(),
                                 chunked.b.data(), kernel);
  for (int j = 0; j < samples; ++j) {
    const double rayleigh_m = 1.5e3 * j, mie_m = 2.0e2 * j * (1.0 + 0.01 * j);
    const double weight_a = 900.0 * std::exp(-0.02 * j), weight_b = 40.0 * std::exp(-0.1 * j);
    sums.add(rayleigh_m, mie_m, weight_a, weight_b);
    transmittance_from_lengths(n, beta_rayleigh.data(), beta_mie.data(), rayleigh_m, mie_m,
                               t.data());
    add_scaled_pair(n, t.data(), weight_a, weight_b, per_sample.a.data(), per_sample.b.data());
  }
  sums.flush();
}

TEST(WeightedTransmittanceSums, DoubleKernelEqualsThePerSampleKernelsAcrossChunks) {
  for (int samples : {0, 1, 4, 31, 32, 33, 65, 130}) {
    Sums chunked, expected;
    sums_of(samples, TransmittanceKernel::double_polynomial, chunked, expected);
    EXPECT_EQ(chunked.a, expected.a) << samples;
    EXPECT_EQ(chunked.b, expected.b) << samples;
  }
}

TEST(WeightedTransmittanceSums, FloatKernelWithinOneInTenMillionAcrossChunks) {
  for (int samples : {0, 1, 4, 31, 32, 33, 65, 130}) {
    Sums chunked, expected;
    sums_of(samples, TransmittanceKernel::float_polynomial, chunked, expected);
    for (std::size_t i = 0; i < expected.a.size(); ++i) {
      EXPECT_NEAR(chunked.a[i], expected.a[i], 1e-7 * expected.a[i]) << samples << ' ' << i;
      EXPECT_NEAR(chunked.b[i], expected.b[i], 1e-7 * expected.b[i]) << samples << ' ' << i;
    }
  }
}

}  // namespace
}  // namespace clearsky
