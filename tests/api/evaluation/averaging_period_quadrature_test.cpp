// The instants of an averaged sample (api/evaluation/averaging_period_quadrature.h): an
// instantaneous sample is its instant; a period is labelled at its end; the weights sum to 1;
// a minute is its midpoint; longer periods have 3 Gauss-Legendre nodes per started hour, so the
// mean of a polynomial of degree 5 over the period is exact.
#include "api/evaluation/averaging_period_quadrature.h"

#include <gtest/gtest.h>

#include <cmath>

namespace clearsky::api {
namespace {

constexpr double kLabel = 1369670400.0;  // 2013-05-27T16:00:00Z

TEST(AveragingPeriodQuadrature, AnInstantaneousSampleIsItsInstant) {
  const auto nodes = averaging_nodes(kLabel, std::nullopt);
  ASSERT_EQ(nodes.size(), 1u);
  EXPECT_EQ(nodes[0].time_utc_s, kLabel);
  EXPECT_EQ(nodes[0].weight, 1.0);
  EXPECT_EQ(representative_time_utc_s(kLabel, std::nullopt), kLabel);
}

TEST(AveragingPeriodQuadrature, AMinuteIsItsMidpointBeforeTheLabel) {
  const auto nodes = averaging_nodes(kLabel, 60.0);
  ASSERT_EQ(nodes.size(), 1u);
  EXPECT_EQ(nodes[0].time_utc_s, kLabel - 30.0);
  EXPECT_EQ(representative_time_utc_s(kLabel, 60.0), kLabel - 30.0);
}

TEST(AveragingPeriodQuadrature, ThreeNodesPerStartedHourInsideThePeriodExactToDegreeFive) {
  for (const double period_s : {61.0, 3600.0, 5400.0, 86400.0}) {
    const auto nodes = averaging_nodes(kLabel, period_s);
    EXPECT_EQ(nodes.size(), 3u * static_cast<std::size_t>(std::ceil(period_s / 3600.0)))
        << period_s;
    double weights = 0, mean = 0;
    // f(t) = x^5 with x the fraction of the period elapsed: its mean over the period is 1/6.
    for (const AveragingNode& n : nodes) {
      EXPECT_GT(n.time_utc_s, kLabel - period_s);
      EXPECT_LT(n.time_utc_s, kLabel);
      weights += n.weight;
      mean += n.weight * std::pow((n.time_utc_s - (kLabel - period_s)) / period_s, 5);
    }
    EXPECT_NEAR(weights, 1.0, 1e-14) << period_s;
    // To the rounding of the node times (unix seconds near 1.4e9: 2.4e-7 s apart, 4e-9 of a
    // 61 s period, times 5 for the fifth power).
    EXPECT_NEAR(mean, 1.0 / 6.0, 5e-8) << period_s;
  }
}

}  // namespace
}  // namespace clearsky::api
