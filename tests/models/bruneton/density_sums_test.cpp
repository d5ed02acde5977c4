// J's two spectral sums in one pass (models/bruneton/density_sums.h) against sum_rows() over
// each sum's own non-zero terms, as the precomputation summed them before: the same bit for bit.
#include "models/bruneton/density_sums.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "models/bruneton/spectral_rows.h"

namespace clearsky::bruneton {
namespace {

void check(int wavelengths) {
  const int stride = padded_stride(wavelengths);
  const int n_rows = 300;
  std::mt19937 random(5);
  std::uniform_real_distribution<float> value(0.0f, 3.0f);
  std::uniform_real_distribution<double> weight(0.0, 1e-2);
  std::uniform_int_distribution<int> kind(0, 5);
  std::vector<float> rows(static_cast<std::size_t>(n_rows) * stride);
  for (float& v : rows) v = value(random);
  for (int trial = 0; trial < 50; ++trial) {
    DensityTerms terms(n_rows);
    std::vector<const float*> list_r, list_m;
    std::vector<float> weights_r, weights_m;
    for (int k = 0; k < n_rows; ++k) {
      // Either weight zero (or both), as the slots a texel's directions do not reach.
      const int which = kind(random);
      const double w_r = which == 0 || which == 2 ? 0.0 : weight(random);
      const double w_m = which == 1 || which == 2 ? 0.0 : weight(random);
      const float* row = rows.data() + static_cast<std::size_t>(k) * stride;
      terms.add(row, w_r, w_m);
      if (w_r != 0.0) {
        list_r.push_back(row);
        weights_r.push_back(static_cast<float>(w_r));
      }
      if (w_m != 0.0) {
        list_m.push_back(row);
        weights_m.push_back(static_cast<float>(w_m));
      }
    }
    std::vector<float> sum_r(stride), sum_m(stride), expected_r(stride), expected_m(stride);
    terms.sum(stride, sum_r.data(), sum_m.data());
    sum_rows(list_r.data(), weights_r.data(), static_cast<int>(list_r.size()), stride,
             expected_r.data());
    sum_rows(list_m.data(), weights_m.data(), static_cast<int>(list_m.size()), stride,
             expected_m.data());
    for (int w = 0; w < stride; ++w) {
      ASSERT_EQ(sum_r[w], expected_r[w]) << trial << " " << w;
      ASSERT_EQ(sum_m[w], expected_m[w]) << trial << " " << w;
    }
  }
}

TEST(DensitySums, BothSumsInOnePassAreTheSumRowsOfEachBitForBit) {
  for (const int wavelengths : {40, 3, 81, 16}) check(wavelengths);
}

}  // namespace
}  // namespace clearsky::bruneton
