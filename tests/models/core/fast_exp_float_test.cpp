// exp_nonpositive_float (single precision) against std::exp: relative error, underflow to exactly 0, NaN propagation.
#include "models/core/fast_exp_float.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace clearsky {
namespace {

TEST(FastExpFloat, RelativeErrorBelow3e7OnTheWholeRange) {
  double worst = 0.0;
  for (int i = 0; i <= 200000; ++i) {
    const float x = -87.0f * static_cast<float>(i) / 200000.0f;
    const double exact = std::exp(static_cast<double>(x));
    worst = std::max(worst, std::abs(exp_nonpositive_float(x) - exact) / exact);
  }
  EXPECT_LT(worst, 3e-7);
  EXPECT_EQ(exp_nonpositive_float(0.0f), 1.0f);
  EXPECT_EQ(exp_nonpositive_float(-0.0f), 1.0f);
}

TEST(FastExpFloat, UnderflowsToExactlyZeroAndStaysInZeroOneOutsideItsDomain) {
  EXPECT_EQ(exp_nonpositive_float(-87.5f), 0.0f);
  EXPECT_EQ(exp_nonpositive_float(-1e30f), 0.0f);
  EXPECT_EQ(exp_nonpositive_float(-std::numeric_limits<float>::infinity()), 0.0f);
  EXPECT_EQ(exp_nonpositive_float(3.0f), 1.0f);
  for (float nan :
       {std::numeric_limits<float>::quiet_NaN(), -std::numeric_limits<float>::quiet_NaN()}) {
    const float v = exp_nonpositive_float(nan);
    EXPECT_TRUE(v >= 0.0f && v <= 1.0f);
  }
}

}  // namespace
}  // namespace clearsky
