// Order statistics and Pareto fronts of the atlas (models/atlas/error_summary.h).
#include "models/atlas/error_summary.h"

#include <gtest/gtest.h>

namespace clearsky::atlas {
namespace {

TEST(AtlasErrorSummary, NearestRankPercentilesOfTwentyValues) {
  std::vector<double> errors;
  for (int i = 20; i >= 1; --i) errors.push_back(0.01 * i);  // 0.01 .. 0.20, unsorted
  const ErrorSummary s = summarise_errors(errors);
  EXPECT_EQ(s.count, 20u);
  EXPECT_DOUBLE_EQ(s.median, 0.10);  // rank 10 of 20
  EXPECT_DOUBLE_EQ(s.p95, 0.19);     // rank 19 of 20
  EXPECT_DOUBLE_EQ(s.max, 0.20);
}

TEST(AtlasErrorSummary, NoErrorsSummariseToZeros) {
  const ErrorSummary s = summarise_errors({});
  EXPECT_EQ(s.count, 0u);
  EXPECT_EQ(s.max, 0.0);
}

TEST(AtlasParetoFront, KeepsOnlyPointsNoOtherBeatsOnCostAndError) {
  const std::vector<std::string> front = pareto_front({{"slow-exact", 10.0, 0.0},
                                                       {"dominated", 5.0, 0.2},
                                                       {"cheap-rough", 1.0, 0.3},
                                                       {"middle", 4.0, 0.1},
                                                       {"same-cost-worse", 4.0, 0.15},
                                                       {"same-error-dearer", 12.0, 0.0}});
  EXPECT_EQ(front, (std::vector<std::string>{"cheap-rough", "middle", "slow-exact"}));
}

}  // namespace
}  // namespace clearsky::atlas
