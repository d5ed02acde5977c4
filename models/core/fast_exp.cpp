// The vector kernels of fast_exp.h.
#include "models/core/fast_exp.h"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace clearsky {

namespace {

// exp(x) for x in [-708, 709] (see fast_exp.h); inlined into the vector loops below.
[[gnu::always_inline]] inline double exp_core(double x) {
  constexpr double kLog2e = 1.4426950408889634074;
  constexpr double kLn2High = 6.93147180369123816490e-01;  // ln2 with 32 trailing zero bits
  constexpr double kLn2Low = 1.90821492927058770002e-10;
  constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52
  const double shifted = x * kLog2e + kRound;
  const double k = shifted - kRound;
  const std::uint64_t k_bits = std::bit_cast<std::uint64_t>(shifted);
  const double r = (x - k * kLn2High) - k * kLn2Low;
  double p = 1.0 / 6227020800.0;  // 1/13!
  p = p * r + 1.0 / 479001600.0;
  p = p * r + 1.0 / 39916800.0;
  p = p * r + 1.0 / 3628800.0;
  p = p * r + 1.0 / 362880.0;
  p = p * r + 1.0 / 40320.0;
  p = p * r + 1.0 / 5040.0;
  p = p * r + 1.0 / 720.0;
  p = p * r + 1.0 / 120.0;
  p = p * r + 1.0 / 24.0;
  p = p * r + 1.0 / 6.0;
  p = p * r + 0.5;
  p = p * r + 1.0;
  p = p * r + 1.0;
  // The low bits of k_bits are k (two's complement); shifting them into the exponent field
  // with the bias gives 2^k for -1022 <= k <= 1023.
  const double scale = std::bit_cast<double>((k_bits + 1023u) << 52);
  return p * scale;
}

// exp(x) for x in [-708, 0] (see add_weighted_transmittances_float in fast_exp.h): k and 2^k as
// in exp_core, exp(r) - 1 in float. The double-to-float conversion of r and the float-to-double
// conversion of the polynomial are exact apart from r's rounding; in the vector loops they
// pack two double vectors into one float vector and back.
[[gnu::always_inline]] inline double exp_float_core(double x) {
  constexpr double kLog2e = 1.4426950408889634074;
  // One double ln2 is enough here: k ln2's error (|k| <= 1022) stays below 1e-13, far under
  // the float rounding of r.
  constexpr double kLn2 = 0.69314718055994530942;
  constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52
  const double shifted = x * kLog2e + kRound;
  const double k = shifted - kRound;
  const std::uint64_t k_bits = std::bit_cast<std::uint64_t>(shifted);
  const auto r = static_cast<float>(x - k * kLn2);
  float p = 1.0f / 5040.0f;
  p = p * r + 1.0f / 720.0f;
  p = p * r + 1.0f / 120.0f;
  p = p * r + 1.0f / 24.0f;
  p = p * r + 1.0f / 6.0f;
  p = p * r + 0.5f;
  p = p * r + 1.0f;
  const float exp_r_minus_1 = p * r;
  const double scale = std::bit_cast<double>((k_bits + 1023u) << 52);
  return static_cast<double>(exp_r_minus_1) * scale + scale;
}

}  // namespace

// On x86-64 a second clone of each kernel uses AVX2 and FMA where the processor has them
// (chosen once at load time by the dynamic linker): 4 doubles per instruction instead of 2.
// The clamps run in a loop of their own (GCC vectorises it too), so that the polynomial loop,
// where the time goes, is a straight run of multiply-adds with no selects.
#if defined(__x86_64__) && defined(__gnu_linux__)
#define CLEARSKY_VECTOR_CLONES [[gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]]
#else
#define CLEARSKY_VECTOR_CLONES
#endif

CLEARSKY_VECTOR_CLONES void exp_nonpositive_in_place(double* values, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) values[i] = std::clamp(values[i], -708.0, 0.0);
  for (std::size_t i = 0; i < n; ++i) values[i] = exp_core(values[i]);
}

CLEARSKY_VECTOR_CLONES void exp_in_place(double* values, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) values[i] = std::clamp(values[i], -708.0, 709.0);
  for (std::size_t i = 0; i < n; ++i) values[i] = exp_core(values[i]);
}

CLEARSKY_VECTOR_CLONES void transmittance_from_lengths(std::size_t n,
                                                       const double* beta_rayleigh_per_m,
                                                       const double* beta_mie_per_m,
                                                       double rayleigh_m, double mie_m,
                                                       double* out) {
  for (std::size_t i = 0; i < n; ++i) {
    out[i] =
        std::clamp(-(beta_rayleigh_per_m[i] * rayleigh_m + beta_mie_per_m[i] * mie_m), -708.0, 0.0);
  }
  for (std::size_t i = 0; i < n; ++i) out[i] = exp_core(out[i]);
}

CLEARSKY_VECTOR_CLONES void add_scaled_pair(std::size_t n, const double* values, double scale_a,
                                            double scale_b, double* sum_a, double* sum_b) {
  for (std::size_t i = 0; i < n; ++i) {
    sum_a[i] += scale_a * values[i];
    sum_b[i] += scale_b * values[i];
  }
}

// The same operations as transmittance_from_lengths and add_scaled_pair, in the same order, so
// that the results are identical. The clamped exponents go through a block on the stack: with
// the clamp in the exponential's loop the compiler evaluates exp_core only in the unclamped
// lanes and no longer fuses the weighting into the sums' multiply-adds, which changes their
// rounding. The clamp is written with value selects, which vectorise (std::clamp selects
// references).
CLEARSKY_VECTOR_CLONES void add_weighted_transmittances(std::size_t n,
                                                        const double* beta_rayleigh_per_m,
                                                        const double* beta_mie_per_m,
                                                        const WeightedSamples& samples,
                                                        double* sum_a, double* sum_b) {
  constexpr std::size_t kBlock = 64;
  double exponent[kBlock];
  for (std::size_t begin = 0; begin < n; begin += kBlock) {
    const std::size_t m = std::min(kBlock, n - begin);
    const double* __restrict beta_rayleigh = beta_rayleigh_per_m + begin;
    const double* __restrict beta_mie = beta_mie_per_m + begin;
    double* __restrict a = sum_a + begin;
    double* __restrict b = sum_b + begin;
    for (std::size_t j = 0; j < samples.count; ++j) {
      const double rayleigh_m = samples.rayleigh_m[j], mie_m = samples.mie_m[j];
      const double weight_a = samples.weight_a[j], weight_b = samples.weight_b[j];
      for (std::size_t i = 0; i < m; ++i) {
        const double x = -(beta_rayleigh[i] * rayleigh_m + beta_mie[i] * mie_m);
        exponent[i] = x < -708.0 ? -708.0 : (0.0 < x ? 0.0 : x);
      }
      for (std::size_t i = 0; i < m; ++i) {
        const double t = exp_core(exponent[i]);
        a[i] += weight_a * t;
        b[i] += weight_b * t;
      }
    }
  }
}

// The per-sample test decides between the loop without clamps (the exponents are then in
// [-708, 0] already: -(beta_R L_R + beta_M L_M) >= -(beta_R,max L_R + beta_M,max L_M) >= -700 up
// to rounding) and the clamped loop of add_weighted_transmittances; one loop each so that the
// compiler vectorises both. Comparisons fail on NaN lengths, which take the clamped loop.
CLEARSKY_VECTOR_CLONES void add_weighted_transmittances_float(std::size_t n,
                                                              const double* beta_rayleigh_per_m,
                                                              const double* beta_mie_per_m,
                                                              const WeightedSamples& samples,
                                                              double* sum_a, double* sum_b) {
  constexpr std::size_t kBlock = 64;
  constexpr double kSafeExponent = 700.0;
  double exponent[kBlock];
  for (std::size_t begin = 0; begin < n; begin += kBlock) {
    const std::size_t m = std::min(kBlock, n - begin);
    const double* __restrict beta_rayleigh = beta_rayleigh_per_m + begin;
    const double* __restrict beta_mie = beta_mie_per_m + begin;
    double* __restrict a = sum_a + begin;
    double* __restrict b = sum_b + begin;
    // The largest coefficients and whether any is negative, on the bit patterns: for doubles
    // with a clear sign bit the integer order is the value order, so the loop vectorises
    // (floating comparisons under trapping math do not). A NaN without its sign bit is the
    // largest and makes the test below fail; one with it counts as negative.
    std::int64_t max_rayleigh_bits = 0, max_mie_bits = 0, any_bits = 0;
    for (std::size_t i = 0; i < m; ++i) {
      const auto rayleigh_bits = std::bit_cast<std::int64_t>(beta_rayleigh[i]);
      const auto mie_bits = std::bit_cast<std::int64_t>(beta_mie[i]);
      max_rayleigh_bits = rayleigh_bits > max_rayleigh_bits ? rayleigh_bits : max_rayleigh_bits;
      max_mie_bits = mie_bits > max_mie_bits ? mie_bits : max_mie_bits;
      any_bits |= rayleigh_bits | mie_bits;
    }
    const bool non_negative = any_bits >= 0;
    const double max_rayleigh = std::bit_cast<double>(max_rayleigh_bits);
    const double max_mie = std::bit_cast<double>(max_mie_bits);
    for (std::size_t j = 0; j < samples.count; ++j) {
      const double rayleigh_m = samples.rayleigh_m[j], mie_m = samples.mie_m[j];
      const double weight_a = samples.weight_a[j], weight_b = samples.weight_b[j];
      if (non_negative && rayleigh_m >= 0.0 && mie_m >= 0.0 &&
          max_rayleigh * rayleigh_m + max_mie * mie_m <= kSafeExponent) {
        for (std::size_t i = 0; i < m; ++i) {
          const double t = exp_float_core(-(beta_rayleigh[i] * rayleigh_m + beta_mie[i] * mie_m));
          a[i] += weight_a * t;
          b[i] += weight_b * t;
        }
        continue;
      }
      for (std::size_t i = 0; i < m; ++i) {
        const double x = -(beta_rayleigh[i] * rayleigh_m + beta_mie[i] * mie_m);
        exponent[i] = x < -708.0 ? -708.0 : (0.0 < x ? 0.0 : x);
      }
      for (std::size_t i = 0; i < m; ++i) {
        const double t = exp_float_core(exponent[i]);
        a[i] += weight_a * t;
        b[i] += weight_b * t;
      }
    }
  }
}

}  // namespace clearsky
