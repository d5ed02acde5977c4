// exp(x) for x <= 0 over arrays, and the other vector kernels of the transmittance loops, written so that the compiler vectorises it (glibc's exp is
// only vectorised under -ffast-math, which this project never uses). The numerical models
// spend most of their time in the transmittances exp(-tau) of 40 wavelengths at every sample
// of a view ray; this is their hot loop.
//
// Method: x = k ln2 + r with k = round(x / ln2) (the 1.5 * 2^52 rounding trick, whose low
// mantissa bits are k), |r| <= ln2 / 2; exp(r) by its Taylor polynomial of degree 13 (error
// (ln2/2)^14 / 14! < 4e-18, below rounding); 2^k assembled in the exponent field. Relative
// error within 2 ulp of std::exp on [-708, 0] (tests/models/core/fast_exp_test.cpp). Inputs are
// clamped to [-708, 0]: below, the result is exp(-708) = 3.3e-307 instead of a smaller number
// (an absolute error no transmittance can notice); above 0 it is 1 (transmittances never
// exceed 1). NaN inputs give unspecified finite values: callers pass finite optical depths.
// Pure; thread-safe.
#pragma once

#include <cstddef>

namespace clearsky {

void exp_nonpositive_in_place(double* values, std::size_t n);

// exp(x) over an array for x of either sign, by the same method: inputs clamped to [-708, 709]
// (exp(709) = 8.2e307, the largest power the exponent field holds), within 2 ulp of std::exp
// there. For the fitted models whose exponents are not known to be <= 0 (Hosek's gradation
// and circumsolar terms, models/hosek/hosek_functions.h).
void exp_in_place(double* values, std::size_t n);

// out[i] = exp(-(beta_rayleigh[i] rayleigh_m + beta_mie[i] mie_m)): the transmittance of the
// optical lengths (optical_depth.h) on n wavelengths, in one vector pass.
void transmittance_from_lengths(std::size_t n, const double* beta_rayleigh_per_m,
                                const double* beta_mie_per_m, double rayleigh_m, double mie_m,
                                double* out);

// sum_a[i] += scale_a values[i]; sum_b[i] += scale_b values[i] (the Rayleigh and Mie
// integrals of the numerical models share each transmittance).
void add_scaled_pair(std::size_t n, const double* values, double scale_a, double scale_b,
                     double* sum_a, double* sum_b);

// The samples of one view ray as the numerical models integrate it: sample j has the optical
// lengths of its path from the observer through the sample to the sun (rayleigh_m[j],
// mie_m[j]) and its two quadrature weights (weight_a[j], weight_b[j]: the Rayleigh and Mie
// weights, density times step).
struct WeightedSamples {
  const double* rayleigh_m;
  const double* mie_m;
  const double* weight_a;
  const double* weight_b;
  std::size_t count;
};

// For each sample j in order: sum_a[i] += weight_a[j] T_j[i], sum_b[i] += weight_b[j] T_j[i],
// T_j[i] = exp(-(beta_rayleigh[i] rayleigh_m[j] + beta_mie[i] mie_m[j])). Bit for bit
// transmittance_from_lengths then add_scaled_pair per sample (tests/models/core/
// fast_exp_test.cpp), in one call per ray instead of two per sample and without storing T:
// the single-scattering sums of Nishita93 and O'Neal. The arrays must not overlap.
void add_weighted_transmittances(std::size_t n, const double* beta_rayleigh_per_m,
                                 const double* beta_mie_per_m, const WeightedSamples& samples,
                                 double* sum_a, double* sum_b);

// add_weighted_transmittances with a shorter exponential, for the numerical models' view rays:
// the reduction x = k ln2 + r (|r| <= ln2 / 2) and the scale 2^k stay in double precision, so
// every exponent down to the -708 clamp keeps its magnitude, while exp(r) - 1 is the Taylor
// polynomial of degree 7 evaluated in single precision (8 lanes per AVX2 instruction instead
// of 4, 7 terms instead of 13; truncation (ln2/2)^8 / 8! < 6e-9) and T = 2^k + 2^k (exp(r) - 1).
// Rounding r and the polynomial to float moves exp(r) - 1 by a few float ulp of a value of at
// most 0.42, so each transmittance is within 1e-7 relative of std::exp of the same exponent
// (6e-8 measured, tests/models/core/fast_exp_test.cpp) over the whole clamped range, and the
// sums, whose weights the models keep >= 0, within 1e-7 relative plus their own rounding. The
// clamps of add_weighted_transmittances ([-708, 0]) hold; a sample whose exponents provably
// lie inside them (non-negative lengths and coefficients, beta_max L <= 700) skips them.
void add_weighted_transmittances_float(std::size_t n, const double* beta_rayleigh_per_m,
                                       const double* beta_mie_per_m, const WeightedSamples& samples,
                                       double* sum_a, double* sum_b);

}  // namespace clearsky
