// Sweep coordinates (models/stress/domain_sweeps.h).
#include "models/stress/domain_sweeps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace clearsky::stress {
namespace {

TEST(DomainSweeps, SunZenithsStepByAFiftiethOfADegreeToTheLargestDeclared) {
  const std::vector<double> z = sun_zeniths_deg(90.0);
  ASSERT_EQ(z.size(), 1801u);
  EXPECT_EQ(z.front(), 0.0);
  EXPECT_NEAR(z.back(), 90.0, 1e-12);
  EXPECT_NEAR(z[1], 0.05, 1e-12);
  EXPECT_NEAR(sun_zeniths_deg(101.39).back(), 101.39, 1e-12);
}

TEST(DomainSweeps, PerSunModelsSweepEveryStepOnlyWhenDenseIsAsked) {
  const std::vector<double> every = swept_sun_zeniths_deg(111.0, false, false);
  const std::vector<double> sparse = swept_sun_zeniths_deg(111.0, true, false);
  const std::vector<double> dense = swept_sun_zeniths_deg(111.0, true, true);
  EXPECT_EQ(every.size(), 2221u);  // 0, 0.05, ..., 111
  EXPECT_EQ(dense, every);
  EXPECT_EQ(sparse, sparse_sun_zeniths_deg(111.0));
  EXPECT_LT(sparse.size(), every.size() / 10);
  // The dense list has no gap wider than a step.
  for (std::size_t i = 1; i < dense.size(); ++i) EXPECT_NEAR(dense[i] - dense[i - 1], 0.05, 1e-9);
}

TEST(DomainSweeps, ViewZenithsAreFinerNearTheHorizon) {
  const std::vector<double> z = view_zeniths_deg(180.0);
  EXPECT_EQ(z.front(), 0.0);
  EXPECT_NEAR(z.back(), 180.0, 1e-9);
  for (std::size_t i = 0; i + 1 < z.size(); ++i) {
    ASSERT_LT(z[i], z[i + 1]);
    const double step = z[i + 1] - z[i];
    if (z[i] >= 88.0 - 1e-9 && z[i + 1] <= 92.0 + 1e-9) {
      EXPECT_NEAR(step, 0.005, 1e-9) << z[i];
    } else {
      EXPECT_NEAR(step, 0.05, 1e-9) << z[i];
    }
  }
  EXPECT_NEAR(view_zeniths_deg(91.0).back(), 91.0, 1e-9);
}

TEST(DomainSweeps, AltitudesRunOnALogScaleBeyondTheTop) {
  const std::vector<double> h = altitudes_m(1e8, 60e3);
  EXPECT_EQ(h.front(), 0.0);
  EXPECT_NEAR(h[1], 1.0, 1e-12);
  EXPECT_NEAR(h.back(), 1e8, 1e-3);
  EXPECT_NEAR(h[2] / h[1], std::pow(10.0, 0.01), 1e-12);
  EXPECT_TRUE(std::is_sorted(h.begin(), h.end()));
  // Every 20 m within 2 km of the top of the atmosphere.
  EXPECT_NE(std::find_if(h.begin(), h.end(), [](double x) { return std::abs(x - 60020) < 1e-6; }),
            h.end());
  EXPECT_NEAR(altitudes_m(60e3, 60e3).back(), 100e3, 1e-6);  // past a 60 km limit: refusals
}

TEST(DomainSweeps, ThinningKeepsBothEnds) {
  const std::vector<double> all = sun_zeniths_deg(90.0);
  const std::vector<double> few = thinned(all, 10);
  ASSERT_EQ(few.size(), 10u);
  EXPECT_EQ(few.front(), 0.0);
  EXPECT_EQ(few.back(), all.back());
  EXPECT_EQ(thinned(all, 0).size(), all.size());
}

TEST(DomainSweeps, ParametersRunFromMinimumToMaximumOrTwiceTheBaseResolution) {
  const ParameterSpec beta{.name = "beta", .min_value = 0, .max_value = 2, .atmosphere = true};
  EXPECT_EQ(parameter_values(beta, parameter_sweep_top(beta, 0.04), 5),
            (std::vector<double>{0, 0.5, 1, 1.5, 2}));
  const ParameterSpec size{.name = "table_mu_size",
                           .default_value = 128,
                           .min_value = 4,
                           .max_value = 512,
                           .integer = true};
  EXPECT_EQ(parameter_sweep_top(size, 32), 64.0);
  EXPECT_EQ(parameter_values(size, 64, 3), (std::vector<double>{4, 34, 64}));
  const ParameterSpec flag{.name = "flag", .min_value = 0, .max_value = 1, .integer = true};
  EXPECT_EQ(parameter_values(flag, parameter_sweep_top(flag, 0), 7), (std::vector<double>{0, 1}));
}

}  // namespace
}  // namespace clearsky::stress
