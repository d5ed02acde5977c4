// The vectorisable exp against std::exp over the whole range the models use it on.
#include "models/core/fast_exp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace clearsky {
namespace {

TEST(FastExp, WithinTwoUlpOfStdExpOnTheNonPositiveRange) {
  std::vector<double> x;
  for (double v = -708.0; v <= 0.0; v += 0.0137) x.push_back(v);
  for (double v = -1.0; v <= 0.0; v += 1e-5) x.push_back(v);
  for (double v : {0.0, -0.0, -1e-300, -1e-17, -0.34657359, -0.34657360, -707.9999}) x.push_back(v);
  std::vector<double> y = x;
  exp_nonpositive_in_place(y.data(), y.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double exact = std::exp(x[i]);
    worst = std::max(worst, std::abs(y[i] - exact) / exact);
  }
  EXPECT_LT(worst, 4.5e-16);
}

TEST(FastExp, ClampsOutsideItsDomain) {
  std::vector<double> y = {1.0, -709.0, -1e6};
  exp_nonpositive_in_place(y.data(), y.size());
  EXPECT_EQ(y[0], 1.0);
  EXPECT_NEAR(y[1], std::exp(-708.0), 1e-15 * std::exp(-708.0));
  EXPECT_LT(y[2], 4e-308);
}

TEST(FastExp, EitherSignMatchesStdExp) {
  std::vector<double> x;
  for (double v = -700.0; v <= 700.0; v += 0.0137) x.push_back(v);
  for (double v : {0.0, -0.0, 1e-300, 0.34657359, 708.9999, -707.9999}) x.push_back(v);
  std::vector<double> y = x;
  exp_in_place(y.data(), y.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double exact = std::exp(x[i]);
    worst = std::max(worst, std::abs(y[i] - exact) / exact);
  }
  EXPECT_LT(worst, 4.5e-16);
  std::vector<double> clamped = {800.0, -1e6};
  exp_in_place(clamped.data(), clamped.size());
  EXPECT_NEAR(clamped[0], std::exp(709.0), 1e-15 * std::exp(709.0));
  EXPECT_LT(clamped[1], 4e-308);
}

// Extinction coefficients shaped like the paper's (Rayleigh ~ lambda^-4, Mie ~ lambda^-0.8, per
// metre at sea level) on n wavelengths from 360 to 830 nm.
void paper_like_betas(std::size_t n, std::vector<double>& rayleigh, std::vector<double>& mie) {
  rayleigh.resize(n);
  mie.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double lambda_um = 0.36 + 0.47 * static_cast<double>(i) / static_cast<double>(n);
    rayleigh[i] = 5.8e-6 * std::pow(0.68 / lambda_um, 4.0);
    mie[i] = 4.4e-5 * std::pow(lambda_um, -0.8);
  }
}

TEST(FastExp, WeightedTransmittancesEqualThePerSampleKernelsBitForBit) {
  // 40 wavelengths (5 AVX-512 vectors), 37 (a remainder) and 1; optical lengths from 0 to
  // far beyond the -708 clamp (1e9 m), weights of both signs' magnitudes.
  for (std::size_t n : {std::size_t{40}, std::size_t{37}, std::size_t{1}}) {
    std::vector<double> beta_rayleigh, beta_mie;
    paper_like_betas(n, beta_rayleigh, beta_mie);
    std::vector<double> rayleigh_m, mie_m, weight_a, weight_b;
    for (int j = 0; j < 23; ++j) {
      rayleigh_m.push_back(j == 0 ? 0.0 : std::pow(10.0, 0.4 * j) * (1.0 + 0.1 * j));
      mie_m.push_back(j == 1 ? 0.0 : 0.17 * std::pow(10.0, 0.4 * j));
      weight_a.push_back(1234.5 * std::exp(-0.3 * j));
      weight_b.push_back(j % 5 == 0 ? 0.0 : 77.0 * std::exp(-1.7 * j));
    }
    std::vector<double> expected_a(n, 0.25), expected_b(n, 0.5), t(n);
    for (std::size_t j = 0; j < rayleigh_m.size(); ++j) {
      transmittance_from_lengths(n, beta_rayleigh.data(), beta_mie.data(), rayleigh_m[j], mie_m[j],
                                 t.data());
      add_scaled_pair(n, t.data(), weight_a[j], weight_b[j], expected_a.data(), expected_b.data());
    }
    std::vector<double> sum_a(n, 0.25), sum_b(n, 0.5);
    add_weighted_transmittances(
        n, beta_rayleigh.data(), beta_mie.data(),
        {rayleigh_m.data(), mie_m.data(), weight_a.data(), weight_b.data(), rayleigh_m.size()},
        sum_a.data(), sum_b.data());
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_EQ(sum_a[i], expected_a[i]) << n << " " << i;
      EXPECT_EQ(sum_b[i], expected_b[i]) << n << " " << i;
    }
    // And against std::exp: each term within 2 ulp, so the sums within a few ulp.
    for (std::size_t i = 0; i < n; ++i) {
      double exact_a = 0.25, exact_b = 0.5;
      for (std::size_t j = 0; j < rayleigh_m.size(); ++j) {
        const double tj = std::exp(-(beta_rayleigh[i] * rayleigh_m[j] + beta_mie[i] * mie_m[j]));
        exact_a += weight_a[j] * tj;
        exact_b += weight_b[j] * tj;
      }
      EXPECT_NEAR(sum_a[i], exact_a, 1e-15 * exact_a);
      EXPECT_NEAR(sum_b[i], exact_b, 1e-15 * exact_b);
    }
  }
}

TEST(FastExp, WeightedTransmittancesOfNoSampleLeaveTheSums) {
  std::vector<double> beta_rayleigh, beta_mie;
  paper_like_betas(8, beta_rayleigh, beta_mie);
  std::vector<double> sum_a(8, 3.0), sum_b(8, 4.0);
  add_weighted_transmittances(8, beta_rayleigh.data(), beta_mie.data(),
                              {nullptr, nullptr, nullptr, nullptr, 0}, sum_a.data(), sum_b.data());
  EXPECT_EQ(sum_a, std::vector<double>(8, 3.0));
  EXPECT_EQ(sum_b, std::vector<double>(8, 4.0));
}

// exp(-beta_i) for each i through the float kernel: one sample of unit Rayleigh length and unit
// weights, so that the sums are the transmittances themselves.
std::vector<double> float_kernel_transmittances(const std::vector<double>& optical_depth) {
  const std::size_t n = optical_depth.size();
  const std::vector<double> no_mie(n, 0.0);
  const double one = 1.0, zero = 0.0;
  std::vector<double> t(n, 0.0), unused(n, 0.0);
  add_weighted_transmittances_float(n, optical_depth.data(), no_mie.data(),
                                    {&one, &zero, &one, &zero, 1}, t.data(), unused.data());
  return t;
}

double worst_relative_error_against_std_exp(const std::vector<double>& optical_depth) {
  const std::vector<double> t = float_kernel_transmittances(optical_depth);
  double worst = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double exact = std::exp(-optical_depth[i]);
    worst = std::max(worst, std::abs(t[i] - exact) / exact);
  }
  return worst;
}

TEST(FastExp, FloatTransmittancesWithinOneInTenMillionOfStdExp) {
  // Optical depths up to 700 take the loop without clamps (beta_max L <= 700), beyond it the
  // clamped one; both within 1e-7 relative (6e-8 measured). A polynomial of one degree less
  // (r^7 / 7! dropped) is 2.1e-7 off (measured) and fails here.
  std::vector<double> fine, whole, beyond;
  for (double v = 0.0; v <= 2.0; v += 3.7e-6) fine.push_back(v);
  for (double v = 0.0; v <= 700.0; v += 0.00137) whole.push_back(v);
  for (double v = 700.0; v <= 708.0; v += 0.0013) beyond.push_back(v);
  for (const auto* depths : {&fine, &whole, &beyond}) {
    EXPECT_LT(worst_relative_error_against_std_exp(*depths), 1e-7) << depths->size();
  }
}

TEST(FastExp, FloatTransmittancesClampLikeTheDoubleKernel) {
  // Beyond 708 the transmittance is exp(-708); a negative exponent's (negative length) is 1.
  const std::vector<double> t = float_kernel_transmittances({709.0, 1e6, -3.0, 0.0});
  EXPECT_NEAR(t[0], std::exp(-708.0), 1e-7 * std::exp(-708.0));
  EXPECT_NEAR(t[1], std::exp(-708.0), 1e-7 * std::exp(-708.0));
  EXPECT_EQ(t[2], 1.0);
  EXPECT_EQ(t[3], 1.0);
}

TEST(FastExp, FloatWeightedTransmittancesWithinOneInTenMillionOfTheExactSums) {
  // The samples of the bit-for-bit test above (optical lengths from 0 to far beyond the clamp,
  // so that both loops run), on 40, 37 and 1 wavelengths: each sum of non-negative terms
  // within 1e-7 relative of the same sum of std::exp.
  for (std::size_t n : {std::size_t{40}, std::size_t{37}, std::size_t{1}}) {
    std::vector<double> beta_rayleigh, beta_mie;
    paper_like_betas(n, beta_rayleigh, beta_mie);
    std::vector<double> rayleigh_m, mie_m, weight_a, weight_b;
    for (int j = 0; j < 23; ++j) {
      rayleigh_m.push_back(j == 0 ? 0.0 : std::pow(10.0, 0.4 * j) * (1.0 + 0.1 * j));
      mie_m.push_back(j == 1 ? 0.0 : 0.17 * std::pow(10.0, 0.4 * j));
      weight_a.push_back(1234.5 * std::exp(-0.3 * j));
      weight_b.push_back(j % 5 == 0 ? 0.0 : 77.0 * std::exp(-1.7 * j));
    }
    std::vector<double> sum_a(n, 0.25), sum_b(n, 0.5);
    add_weighted_transmittances_float(
        n, beta_rayleigh.data(), beta_mie.data(),
        {rayleigh_m.data(), mie_m.data(), weight_a.data(), weight_b.data(), rayleigh_m.size()},
        sum_a.data(), sum_b.data());
    for (std::size_t i = 0; i < n; ++i) {
      double exact_a = 0.25, exact_b = 0.5;
      for (std::size_t j = 0; j < rayleigh_m.size(); ++j) {
        const double tj = std::exp(-(beta_rayleigh[i] * rayleigh_m[j] + beta_mie[i] * mie_m[j]));
        exact_a += weight_a[j] * tj;
        exact_b += weight_b[j] * tj;
      }
      EXPECT_NEAR(sum_a[i], exact_a, 1e-7 * exact_a) << n << " " << i;
      EXPECT_NEAR(sum_b[i], exact_b, 1e-7 * exact_b) << n << " " << i;
    }
  }
}

TEST(FastExp, FloatWeightedTransmittancesOfNoSampleLeaveTheSums) {
  std::vector<double> beta_rayleigh, beta_mie;
  paper_like_betas(8, beta_rayleigh, beta_mie);
  std::vector<double> sum_a(8, 3.0), sum_b(8, 4.0);
  add_weighted_transmittances_float(8, beta_rayleigh.data(), beta_mie.data(),
                                    {nullptr, nullptr, nullptr, nullptr, 0}, sum_a.data(),
                                    sum_b.data());
  EXPECT_EQ(sum_a, std::vector<double>(8, 3.0));
  EXPECT_EQ(sum_b, std::vector<double>(8, 4.0));
}

}  // namespace
}  // namespace clearsky
