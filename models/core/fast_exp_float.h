// exp(x) for x <= 0 (precondition) in single precision, written without branches or library calls so that
// loops over wavelengths vectorise (transmittances exp(-tau) of the per-sun precomputations
// are evaluated hundreds of millions of times). Relative error below 3e-7 against std::exp
// on [-87, 0]; arguments below -87 (transmittance under 1.6e-38) give exactly 0, never a
// denormal; arguments >= 0 give 1 (transmittances never exceed 1). NaN inputs give a finite
// value in [0, 1] (callers pass finite optical depths); no input reaches undefined behaviour.
// Tested in tests/models/core/fast_exp_float_test.cpp.
#pragma once

#include <bit>
#include <cstdint>

namespace clearsky {

inline float exp_nonpositive_float(float x) {
  // exp(x) = 2^n exp(f), n = round(x / ln 2), f = x - n ln 2 in [-ln2/2, ln2/2]; ln 2 split in
  // a high part exact in float and a low part (Cody and Waite) so that f keeps full precision.
  constexpr float kLog2e = 1.44269504088896341f;
  constexpr float kLn2High = 0.693145751953125f;
  constexpr float kLn2Low = 1.42860682030941723e-6f;
  // Value selects rather than std::min/max (which select references and keep GCC from
  // vectorising the loop under the default -ftrapping-math).
  const float keep = x >= -87.0f ? 1.0f : 0.0f;
  // Clamp to [-87, 0] on the bit patterns (sign and magnitude: for x < 0 a larger magnitude is
  // a larger unsigned value; a clear sign bit means x >= 0 or +NaN): integer selects, so that
  // the float-to-int conversion below never sees an out-of-range value or a NaN, and GCC
  // vectorises the loop under the default -ftrapping-math.
  const std::int32_t bits = std::bit_cast<std::int32_t>(x);
  constexpr std::int32_t kLowestBits = std::bit_cast<std::int32_t>(-87.0f);
  // Negative floats are negative integers here, more negative floats larger integers.
  const std::int32_t low_clamped = bits > kLowestBits ? kLowestBits : bits;
  const std::int32_t sign_mask = bits >> 31;  // all ones for x < 0 (or -NaN), else 0
  const float clamped = std::bit_cast<float>(low_clamped & sign_mask);
  // Truncation of a value <= 0 shifted by -0.5 rounds to nearest (conversion vectorises).
  const auto n = static_cast<std::int32_t>(clamped * kLog2e - 0.5f);
  const float nf = static_cast<float>(n);
  const float f = (clamped - nf * kLn2High) - nf * kLn2Low;
  // Taylor polynomial of degree 7 on |f| <= 0.347: truncation error < 2e-8 relative.
  float p = 1.0f / 5040.0f;
  p = p * f + 1.0f / 720.0f;
  p = p * f + 1.0f / 120.0f;
  p = p * f + 1.0f / 24.0f;
  p = p * f + 1.0f / 6.0f;
  p = p * f + 0.5f;
  p = p * f + 1.0f;
  p = p * f + 1.0f;
  // 2^n by building the float exponent; n >= -126 since clamped >= -87.
  const float scale = std::bit_cast<float>(static_cast<std::uint32_t>(n + 127) << 23);
  return keep * p * scale;
}

}  // namespace clearsky
