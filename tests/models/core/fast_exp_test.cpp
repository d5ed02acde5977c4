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

}  // namespace
}  // namespace clearsky
