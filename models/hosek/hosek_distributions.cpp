// The vector loops of hosek_distributions.h. This file is compiled with -fno-math-errno (GCC
// vectorises std::sqrt only when it need not set errno; the values are the same correctly
// rounded square roots, of arguments >= (1 - g)^2 > 0) and -ffp-contract=off (the AVX2 clone
// must not fuse multiplies and adds, so that every processor rounds as distribution() does on
// the baseline x86-64 build): models/CMakeLists.txt.
#include "models/hosek/hosek_distributions.h"

#include <cmath>

#include "models/core/fast_exp.h"

namespace clearsky::hosek {
namespace {

// On x86-64 an AVX2 clone (4 doubles per instruction instead of 2), chosen once at load time by
// the dynamic linker where the processor has it.
#if defined(__x86_64__) && defined(__gnu_linux__)
#define CLEARSKY_HOSEK_CLONES [[gnu::target_clones("arch=x86-64-v3", "default")]]
#else
#define CLEARSKY_HOSEK_CLONES
#endif

// The exponents of the gradation term exp(B / (cos theta + 0.01)) and of the circumsolar term
// exp(E gamma), side by side in one array of 2 n.
CLEARSKY_HOSEK_CLONES void exponents_of(std::size_t n, const double* b, const double* e,
                                        double inverse_cos_theta_plus, double gamma_rad,
                                        double* exponents) {
  for (std::size_t t = 0; t < n; ++t) exponents[t] = b[t] * inverse_cos_theta_plus;
  for (std::size_t t = 0; t < n; ++t) exponents[n + t] = e[t] * gamma_rad;
}

// Eq. 9 with its exponentials given: (1 + A gradation) (C + D peak + F cos^2 gamma + G chi +
// I sqrt(cos theta)), chi = (1 + cos^2 gamma) / (1 + g^2 - 2 g cos gamma)^(3/2), each sum and
// product in distribution()'s order.
CLEARSKY_HOSEK_CLONES void combine(std::size_t n, const std::array<const double*, 9>& c,
                                   const double* mie_constant, const double* mie_slope,
                                   const ViewTerms& v, const double* gradation, const double* peak,
                                   double* __restrict f) {
  const double* a = c[0];
  const double* c_term = c[2];
  const double* d = c[3];
  const double* f_term = c[5];
  const double* g_term = c[6];
  const double* i_term = c[7];
  const double cos_gamma = v.cos_gamma, cos2_gamma = v.cos2_gamma;
  const double sqrt_cos_theta = v.sqrt_cos_theta;
  const double mie_numerator = 1.0 + cos2_gamma;
  for (std::size_t t = 0; t < n; ++t) {
    const double mie_base = mie_constant[t] - mie_slope[t] * cos_gamma;
    const double mie = mie_numerator / (mie_base * std::sqrt(mie_base));
    f[t] = (1.0 + a[t] * gradation[t]) * (c_term[t] + d[t] * peak[t] + f_term[t] * cos2_gamma +
                                          g_term[t] * mie + i_term[t] * sqrt_cos_theta);
  }
}

}  // namespace

std::uint32_t Distributions::add(const Coefficients& c) {
  for (int k = 0; k < kCoefficientCount; ++k) coefficient_[k].push_back(c[k]);
  const double g = c[8];
  mie_constant_.push_back(1.0 + g * g);
  mie_slope_.push_back(2.0 * g);
  return static_cast<std::uint32_t>(size() - 1);
}

void Distributions::evaluate(const ViewTerms& v, double* exponents, double* f) const {
  const std::size_t n = size();
  exponents_of(n, coefficient_[1].data(), coefficient_[4].data(), v.inverse_cos_theta_plus,
               v.gamma_rad, exponents);
  exp_in_place(exponents, 2 * n);
  std::array<const double*, 9> c{};
  for (int k = 0; k < kCoefficientCount; ++k) c[k] = coefficient_[k].data();
  combine(n, c, mie_constant_.data(), mie_slope_.data(), v, exponents, exponents + n, f);
}

}  // namespace clearsky::hosek
