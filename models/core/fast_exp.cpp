// The vectorisable exp of fast_exp.h.
#include "models/core/fast_exp.h"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace clearsky {

// On x86-64 a second clone uses AVX2 and FMA where the processor has them (chosen once at
// load time by the dynamic linker): 4 doubles per instruction instead of 2.
#if defined(__x86_64__) && defined(__gnu_linux__)
[[gnu::target_clones("arch=x86-64-v3", "default")]]
#endif
void exp_nonpositive_in_place(double* values, std::size_t n) {
  // The clamps first, in a loop of their own: with trapping math (the default) comparisons
  // keep a loop from being vectorised, and the polynomial loop below is where the time goes.
  for (std::size_t i = 0; i < n; ++i) values[i] = std::clamp(values[i], -708.0, 0.0);
  constexpr double kLog2e = 1.4426950408889634074;
  constexpr double kLn2High = 6.93147180369123816490e-01;  // ln2 with 32 trailing zero bits
  constexpr double kLn2Low = 1.90821492927058770002e-10;
  constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52
  for (std::size_t i = 0; i < n; ++i) {
    const double x = values[i];
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
    // with the bias gives 2^k for -1022 <= k <= 0.
    const double scale = std::bit_cast<double>((k_bits + 1023u) << 52);
    values[i] = p * scale;
  }
}

}  // namespace clearsky
