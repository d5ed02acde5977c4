// Gauss-Legendre exactness and trapezoid weights.
#include "models/core/quadrature.h"

#include <gtest/gtest.h>

#include <cmath>

#include "models/core/numeric.h"

namespace clearsky {
namespace {

TEST(Quadrature, GaussLegendreIsExactForPolynomialsOfDegree2nMinus1) {
  for (int n : {1, 2, 5, 16}) {
    const int degree = 2 * n - 1;
    double sum = 0.0;
    for (const auto& [x, w] : gauss_legendre(n, 0.0, 2.0)) sum += w * std::pow(x, degree);
    EXPECT_NEAR(sum, std::pow(2.0, degree + 1) / (degree + 1), 1e-11 * std::pow(2.0, degree + 1))
        << n;
  }
}

TEST(Quadrature, GaussLegendreIntegratesSmoothFunctions) {
  double sum = 0.0;
  for (const auto& [x, w] : gauss_legendre(24, 0.0, kPi)) sum += w * std::sin(x);
  EXPECT_NEAR(sum, 2.0, 1e-13);
  EXPECT_THROW(gauss_legendre(0, 0.0, 1.0), std::invalid_argument);
}

TEST(Quadrature, TrapezoidWeightsSumToTheInterval) {
  const auto w = trapezoid_weights(5, 1.0, 3.0);
  EXPECT_DOUBLE_EQ(w[0], 0.25);
  EXPECT_DOUBLE_EQ(w[2], 0.5);
  double total = 0.0;
  for (double x : w) total += x;
  EXPECT_DOUBLE_EQ(total, 2.0);
}

}  // namespace
}  // namespace clearsky
