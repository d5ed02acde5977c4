// floats_to_halves (api/skydome/half_conversion.h) against Imath's half(float), which the
// per-pixel path uses: the same bits for every float but NaN, checked on every combination of
// sign, exponent and the 14 low mantissa bits (where the rounding of the 13 dropped bits and
// its ties lie) under two patterns of the high bits, and on a sweep of all floats in steps of
// a prime, through arrays whose lengths are no multiple of 8 (the F16C loop's tail).
#include "api/skydome/half_conversion.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

namespace clearsky::api {
namespace {

void expect_as_imath(const std::vector<float>& values) {
  std::vector<half> out(values.size());
  floats_to_halves(values.data(), out.data(), values.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (out[i].bits() != half(values[i]).bits()) {
      if (++differing <= 5)
        ADD_FAILURE() << "float bits " << std::hex << std::bit_cast<std::uint32_t>(values[i])
                      << ": " << out[i].bits() << " instead of " << half(values[i]).bits();
    }
  }
  EXPECT_EQ(differing, 0u);
}

TEST(HalfConversion, GivesImathsBitsForEveryRoundingCase) {
  std::vector<float> values;
  for (std::uint32_t sign = 0; sign < 2; ++sign) {
    for (std::uint32_t exponent = 0; exponent < 255; ++exponent) {  // 255: infinity and NaN
      for (std::uint32_t high : {0u, 0x1a5u}) {                     // mantissa bits 14 to 22
        for (std::uint32_t low = 0; low < (1u << 14); ++low) {
          const std::uint32_t bits = (sign << 31) | (exponent << 23) | (high << 14) | low;
          values.push_back(std::bit_cast<float>(bits));
        }
      }
    }
  }
  values.push_back(INFINITY);
  values.push_back(-INFINITY);
  values.push_back(65504.0f);
  values.push_back(65520.0f);  // the tie between 65504 and infinity
  values.push_back(7.0f);      // an odd length
  expect_as_imath(values);
}

TEST(HalfConversion, GivesImathsBitsOverASweepOfAllFloats) {
  std::vector<float> values;
  for (std::uint64_t bits = 0; bits < (std::uint64_t{1} << 32); bits += 65521) {
    const float f = std::bit_cast<float>(static_cast<std::uint32_t>(bits));
    if (!std::isnan(f)) values.push_back(f);
  }
  expect_as_imath(values);
}

}  // namespace
}  // namespace clearsky::api
