// Single scattering's sums along a view ray (models/bruneton/single_scattering_sums.h) against
// one sample at a time through sum_rows(), as the precomputation summed them before: the same
// bit for bit.
#include "models/bruneton/single_scattering_sums.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "models/bruneton/spectral_rows.h"

namespace clearsky::bruneton {
namespace {

void check(int wavelengths) {
  const int stride = padded_stride(wavelengths);
  const int n_rows = 40, n_samples = 51;
  std::mt19937 random(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::uniform_int_distribution<int> pick(0, n_rows - 1), rows_per_sample(1, 4);
  // Transmittance rows and view transmittances in (0, 1), as the tables hold them.
  std::vector<float> table(static_cast<std::size_t>(n_rows) * stride);
  for (float& v : table) v = unit(random);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<float> views(static_cast<std::size_t>(n_samples) * stride);
    for (float& v : views) v = unit(random);
    std::vector<SunlitSample> samples(n_samples);
    for (int i = 0; i < n_samples; ++i) {
      SunlitSample& s = samples[i];
      s.count = rows_per_sample(random);
      for (int k = 0; k < s.count; ++k) {
        s.rows[k] = table.data() + static_cast<std::size_t>(pick(random)) * stride;
        s.weights[k] = unit(random);
      }
      s.view = views.data() + static_cast<std::size_t>(i) * stride;
      s.weight_r = unit(random) * 1e3f;
      s.weight_m = unit(random) * 1e2f;
    }
    // Both start from the same non-zero sums (a texel's sums are zero at first; any start is
    // added to alike).
    std::vector<float> sum_r(stride), sum_m(stride);
    for (int w = 0; w < stride; ++w) {
      sum_r[w] = unit(random);
      sum_m[w] = unit(random);
    }
    std::vector<float> expected_r = sum_r, expected_m = sum_m;
    add_sunlit_samples(samples.data(), n_samples, stride, sum_r.data(), sum_m.data());
    add_sunlit_samples_reference(samples.data(), n_samples, stride, expected_r.data(),
                                 expected_m.data());
    for (int w = 0; w < stride; ++w) {
      ASSERT_EQ(sum_r[w], expected_r[w]) << trial << " " << w;
      ASSERT_EQ(sum_m[w], expected_m[w]) << trial << " " << w;
    }
  }
}

TEST(SingleScatteringSums, RegisterSumsAreTheOneSampleAtATimeSumsBitForBit) {
  for (const int wavelengths : {40, 3, 81, 16}) check(wavelengths);
}

}  // namespace
}  // namespace clearsky::bruneton
