// The chunked single-scattering sums against the per-sample kernels they replace: the same
// bits for rays shorter and longer than a chunk (Nishita93's rays have about 65 samples).
#include "models/core/weighted_transmittance_sums.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "models/core/fast_exp.h"

namespace clearsky {
namespace {

TEST(WeightedTransmittanceSums, EqualThePerSampleKernelsAcrossChunks) {
  const std::size_t n = 40;
  std::vector<double> beta_rayleigh(n), beta_mie(n);
  for (std::size_t i = 0; i < n; ++i) {
    beta_rayleigh[i] = 3e-5 * std::pow(0.5 + 0.01 * static_cast<double>(i), -4.0) / 16.0;
    beta_mie[i] = 2e-5 + 1e-7 * static_cast<double>(i);
  }
  for (int samples : {0, 1, 4, 31, 32, 33, 65, 130}) {
    std::vector<double> sum_a(n, -1.0), sum_b(n, -1.0);  // zeroed by the constructor
    std::vector<double> expected_a(n, 0.0), expected_b(n, 0.0), t(n);
    WeightedTransmittanceSums sums(n, beta_rayleigh.data(), beta_mie.data(), sum_a.data(),
                                   sum_b.data());
    for (int j = 0; j < samples; ++j) {
      const double rayleigh_m = 1.5e3 * j, mie_m = 2.0e2 * j * (1.0 + 0.01 * j);
      const double weight_a = 900.0 * std::exp(-0.02 * j), weight_b = 40.0 * std::exp(-0.1 * j);
      sums.add(rayleigh_m, mie_m, weight_a, weight_b);
      transmittance_from_lengths(n, beta_rayleigh.data(), beta_mie.data(), rayleigh_m, mie_m,
                                 t.data());
      add_scaled_pair(n, t.data(), weight_a, weight_b, expected_a.data(), expected_b.data());
    }
    sums.flush();
    EXPECT_EQ(sum_a, expected_a) << samples;
    EXPECT_EQ(sum_b, expected_b) << samples;
  }
}

}  // namespace
}  // namespace clearsky
