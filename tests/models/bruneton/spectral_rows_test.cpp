// The spectral row kernels and the binary16 conversions against their definitions.
#include "models/bruneton/spectral_rows.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace clearsky::bruneton {
namespace {

TEST(HalfFloat, ExactValuesRoundTrip) {
  // Values representable in binary16 convert exactly both ways.
  for (float v :
       {0.0f, 1.0f, -2.0f, 0.5f, 65504.0f, 0x1p-14f, 0x1p-24f, 3.0f * 0x1p-20f, 1.0009765625f}) {
    EXPECT_EQ(half_to_float(float_to_half(v)), v) << v;
  }
  EXPECT_EQ(float_to_half(1.0f), 0x3c00);
  EXPECT_EQ(float_to_half(-2.0f), 0xc000);
  EXPECT_EQ(float_to_half(0x1p-24f), 0x0001);
}

TEST(HalfFloat, RoundsToNearestEven) {
  // 1 + 2^-11 lies halfway between 1 and 1 + 2^-10: ties go to the even mantissa (1).
  EXPECT_EQ(float_to_half(1.0f + 0x1p-11f), 0x3c00);
  // 1 + 3 * 2^-11 lies halfway between 1 + 2^-10 (odd) and 1 + 2^-9 (even).
  EXPECT_EQ(float_to_half(1.0f + 3.0f * 0x1p-11f), 0x3c02);
  EXPECT_EQ(float_to_half(1.0f + 0x1p-11f + 0x1p-20f), 0x3c01);
  // Relative error of any normal value at most 2^-11.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> exponent(-14.0f, 15.0f);
  for (int i = 0; i < 10000; ++i) {
    const float v = std::exp2(exponent(rng));
    EXPECT_LE(std::abs(half_to_float(float_to_half(v)) - v), v * 0x1p-11f) << v;
  }
}

TEST(HalfFloat, PortableConversionMatchesTheFastPath) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> exponent(-30.0f, 15.0f);
  std::vector<float> in(4099);
  for (float& v : in) v = std::exp2(exponent(rng)) * (rng() % 2 == 0 ? 1.0f : -1.0f);
  std::vector<std::uint16_t> fast(in.size()), slow(in.size());
  floats_to_halves(in.data(), 0.75f, fast.data(), in.size());
  portable::floats_to_halves(in.data(), 0.75f, slow.data(), in.size());
  EXPECT_EQ(fast, slow);
}

TEST(SpectralRows, WeightedSumOfHalfRows) {
  constexpr int kStride = 40;
  std::vector<std::uint16_t> a(kStride), b(kStride);
  for (int i = 0; i < kStride; ++i) {
    a[i] = float_to_half(static_cast<float>(i));
    b[i] = float_to_half(0.25f * static_cast<float>(i));
  }
  const std::uint16_t* rows[] = {a.data(), b.data()};
  const float weights[] = {0.5f, 2.0f};
  std::vector<float> fast(kStride), slow(kStride);
  sum_rows(rows, weights, 2, kStride, fast.data());
  portable::sum_rows(rows, weights, 2, kStride, slow.data());
  for (int i = 0; i < kStride; ++i) {
    EXPECT_FLOAT_EQ(fast[i], static_cast<float>(i)) << i;  // 0.5 i + 2 * 0.25 i
    EXPECT_FLOAT_EQ(slow[i], fast[i]) << i;
  }
}

// With AVX2 each lane adds its rows in order by fused multiply-adds, however many vectors a
// pass holds (spectral_rows.cpp): the same bits as std::fma row after row, for strides of 1 to
// 17 vectors (blocks of 8 and the remainders) and up to 48 rows (a lookup's three 4D tables).
TEST(SpectralRows, HalfSumIsEachLanesFusedMultiplyAddsInRowOrder) {
  if (!using_avx2_kernels()) GTEST_SKIP() << "no AVX2/F16C: the portable sum is not fused";
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> value(0.0f, 3.0f), weight(0.0f, 0.2f);
  for (int stride = 8; stride <= 136; stride += 8) {
    for (int count : {0, 1, 7, 24, 48}) {
      std::vector<std::vector<std::uint16_t>> table(static_cast<std::size_t>(count));
      std::vector<const std::uint16_t*> rows;
      std::vector<float> weights;
      for (auto& row : table) {
        row.resize(static_cast<std::size_t>(stride));
        for (auto& h : row) h = float_to_half(value(rng));
        rows.push_back(row.data());
        weights.push_back(weight(rng));
      }
      std::vector<float> out(static_cast<std::size_t>(stride), -1.0f);
      sum_rows(rows.data(), weights.data(), count, stride, out.data());
      for (int i = 0; i < stride; ++i) {
        float expected = 0.0f;
        for (int k = 0; k < count; ++k)
          expected = std::fma(weights[k], half_to_float(rows[k][i]), expected);
        ASSERT_EQ(out[i], expected) << "stride " << stride << " rows " << count << " lane " << i;
      }
    }
  }
}

TEST(SpectralRows, WeightedSumOfFloatRows) {
  constexpr int kStride = 16;
  std::vector<float> a(kStride, 1.0f), b(kStride, 3.0f), out(kStride, -1.0f);
  const float* rows[] = {a.data(), b.data()};
  const float weights[] = {0.25f, 0.25f};
  sum_rows(rows, weights, 2, kStride, out.data());
  for (float v : out) EXPECT_FLOAT_EQ(v, 1.0f);
  sum_rows(rows, weights, 0, kStride, out.data());
  for (float v : out) EXPECT_EQ(v, 0.0f);
  EXPECT_EQ(padded_stride(40), 40);
  EXPECT_EQ(padded_stride(15), 16);
  EXPECT_EQ(padded_stride(3), 8);
}

}  // namespace
}  // namespace clearsky::bruneton
