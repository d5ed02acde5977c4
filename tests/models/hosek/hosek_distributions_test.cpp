// Hosek's distributions of a view as vector loops (models/hosek/hosek_distributions.h) against
// hosek::distribution(), the formula of the paper (Hosek and Wilkie 2012, eq. 9): bit for bit
// with the same exponentials (exp_in_place, fast_exp.h), and within 1e-12 relative with
// std::exp's, over the bands, turbidities, albedos, solar elevations and views of the model's
// domain (the horizon and the sun's direction included).
#include "models/hosek/hosek_distributions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "models/core/fast_exp.h"
#include "models/core/geometry.h"

namespace clearsky {
namespace {

// distribution() with its two exponentials given: the same operations in the same order.
double distribution_with(const hosek::Coefficients& c, const hosek::ViewTerms& v, double gradation,
                         double peak) {
  const double mie_base = 1.0 + c[8] * c[8] - 2.0 * c[8] * v.cos_gamma;
  const double mie = (1.0 + v.cos2_gamma) / (mie_base * std::sqrt(mie_base));
  return (1.0 + c[0] * gradation) *
         (c[2] + c[3] * peak + c[5] * v.cos2_gamma + c[6] * mie + c[7] * v.sqrt_cos_theta);
}

// The configurations of a few suns and atmospheres: every band, cooked as the model cooks them.
std::vector<hosek::Coefficients> configurations() {
  std::vector<hosek::Coefficients> all;
  const auto& bands = hosek::Tables::get().spectral;
  for (double turbidity : {1.0, 2.53, 6.7, 10.0}) {
    for (double albedo : {0.0, 0.08, 0.6, 1.0}) {
      for (double elevation_deg : {0.0, 2.0, 10.0, 35.0, 70.0, 90.0}) {
        for (const auto& band : bands) {
          all.push_back(
              hosek::cook(band, turbidity, albedo, elevation_deg * kPi / 180.0).coefficients);
        }
      }
    }
  }
  return all;
}

// Views from the zenith to the horizon, from the sun's direction (gamma = 0) to its opposite.
std::vector<hosek::ViewTerms> views() {
  std::vector<hosek::ViewTerms> all;
  for (double cos_theta : {1.0, 0.9, 0.5, 0.2, 0.05, 0.01, 1e-4, 0.0}) {
    for (double cos_gamma : {1.0, 0.99999, 0.999, 0.9, 0.3, 0.0, -0.4, -0.95, -1.0}) {
      all.push_back(hosek::view_terms(cos_theta, cos_gamma));
    }
  }
  return all;
}

TEST(HosekDistributions, EqualDistributionBitForBitWithTheSameExponentials) {
  const auto cooked = configurations();
  hosek::Distributions distributions;
  for (std::size_t t = 0; t < cooked.size(); ++t) {
    EXPECT_EQ(distributions.add(cooked[t]), t);
  }
  ASSERT_EQ(distributions.size(), cooked.size());
  std::vector<double> exponents(2 * cooked.size()), f(cooked.size());
  for (const hosek::ViewTerms& v : views()) {
    distributions.evaluate(v, exponents.data(), f.data());
    for (std::size_t t = 0; t < cooked.size(); ++t) {
      const hosek::Coefficients& c = cooked[t];
      double e[2] = {c[1] * v.inverse_cos_theta_plus, c[4] * v.gamma_rad};
      exp_in_place(e, 2);
      ASSERT_EQ(f[t], distribution_with(c, v, e[0], e[1]))
          << "configuration " << t << ", gamma " << v.gamma_rad << ", sqrt(cos theta) "
          << v.sqrt_cos_theta;
    }
  }
}

TEST(HosekDistributions, AgreeWithTheFormulaOfStdExpWithin1e12) {
  const auto cooked = configurations();
  hosek::Distributions distributions;
  for (const auto& c : cooked) distributions.add(c);
  std::vector<double> exponents(2 * cooked.size()), f(cooked.size());
  double largest = 0.0;
  for (const hosek::ViewTerms& v : views()) {
    distributions.evaluate(v, exponents.data(), f.data());
    for (std::size_t t = 0; t < cooked.size(); ++t) {
      const double expected = hosek::distribution(cooked[t], v);
      ASSERT_TRUE(std::isfinite(f[t]));
      // Relative to the value, or to its sum's largest term where the sum nearly cancels (the
      // fit crossing zero at the horizon with the sun low).
      const hosek::Coefficients& c = cooked[t];
      const double scale = std::max(
          std::abs(expected), std::abs(1.0 + c[0] * std::exp(c[1] * v.inverse_cos_theta_plus)) *
                                  (std::abs(c[2]) + std::abs(c[3] * std::exp(c[4] * v.gamma_rad))));
      const double relative = std::abs(f[t] - expected) / scale;
      largest = std::max(largest, relative);
      EXPECT_LE(relative, 1e-12) << "configuration " << t << ": " << f[t] << " against "
                                 << expected;
    }
  }
  RecordProperty("largest_relative_difference", std::to_string(largest));
}

}  // namespace
}  // namespace clearsky
