// The neighbour-jump summary of a sweep (models/stress/neighbour_jumps.h).
#include "models/stress/neighbour_jumps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace clearsky::stress {
namespace {

Chain chain_of(const std::vector<double>& coordinates, const std::vector<double>& values) {
  Chain chain{"test", {}};
  for (std::size_t i = 0; i < values.size(); ++i)
    chain.points.push_back({coordinates[i], true, {values[i]}, SampleStatus::ok});
  return chain;
}

TEST(NeighbourJumps, FindsTheLargestRelativeJumpAndWhereItIs) {
  const std::vector<Chain> chains = {chain_of({0, 1, 2, 3}, {1.0, 1.1, 2.2, 2.3})};
  const std::vector<double> wavelengths = {550.0};
  SweepSummary summary;
  summarize_jumps(chains, wavelengths, {}, summary);
  EXPECT_NEAR(summary.worst_relative_jump, 0.5, 1e-12);  // 1.1 -> 2.2
  EXPECT_EQ(summary.worst_from, 1.0);
  EXPECT_EQ(summary.worst_to, 2.0);
  EXPECT_EQ(summary.worst_chain, "test");
  EXPECT_EQ(summary.points, 4u);
}

TEST(NeighbourJumps, RefusedSamplesBreakTheChain) {
  Chain chain = chain_of({0, 1, 2}, {1.0, 100.0, 1.0});
  chain.points[1] = {1.0, false, {}, SampleStatus::invalid_input};
  const std::vector<double> wavelengths = {550.0};
  SweepSummary summary;
  summarize_jumps(std::vector<Chain>{chain}, wavelengths, {}, summary);
  EXPECT_EQ(summary.worst_relative_jump, 0.0);
}

TEST(NeighbourJumps, ValuesDecayingToNothingAreMeasuredAgainstAFloorOfThePeak) {
  // 1e-6 -> 1e-8 is a factor of 100, but both are far below 1e-2 of the peak (1).
  const std::vector<Chain> chains = {chain_of({0, 1, 2}, {1.0, 1e-6, 1e-8})};
  const std::vector<double> wavelengths = {550.0};
  SweepSummary summary;
  summarize_jumps(chains, wavelengths, {}, summary);
  EXPECT_NEAR(summary.worst_relative_jump, 1.0 - 1e-6, 1e-12);  // 1 -> 1e-6
  EXPECT_EQ(summary.worst_to, 1.0);
}

TEST(NeighbourJumps, DocumentedJumpsAreReportedApartByName) {
  const std::vector<Chain> chains = {chain_of({89.9, 90.0, 90.1, 90.2}, {1.0, 1.01, 3.0, 3.01})};
  const std::vector<double> wavelengths = {550.0};
  const std::vector<DocumentedJump> documented = {{"ground_horizon", 90.05}};
  SweepSummary summary;
  summarize_jumps(chains, wavelengths, documented, summary);
  EXPECT_LT(summary.worst_relative_jump, 0.011);
  ASSERT_EQ(summary.excluded.size(), 1u);
  EXPECT_EQ(summary.excluded[0].name, "ground_horizon");
  EXPECT_NEAR(summary.excluded[0].relative_jump, (3.0 - 1.01) / 3.0, 1e-12);
}

TEST(NeighbourJumps, JumpsBesideARefusalOutsideTheFitDomainAreTheFitDomainEdge) {
  // A fitted spectrum falling linearly to zero, then refused (models/core/fit_domain.h).
  Chain chain = chain_of({0, 1, 2, 3, 4}, {4.0, 3.0, 2.0, 0.01, 0.0});
  chain.points[4] = {4.0, false, {}, SampleStatus::outside_fit_domain};
  const std::vector<double> wavelengths = {550.0};
  SweepSummary summary;
  summarize_jumps(std::vector<Chain>{chain}, wavelengths, {}, summary);
  EXPECT_EQ(summary.worst_relative_jump, 0.0);
  ASSERT_EQ(summary.excluded.size(), 1u);
  EXPECT_EQ(summary.excluded[0].name, "fit_domain_edge");
  EXPECT_NEAR(summary.excluded[0].relative_jump, (2.0 - 0.01) / 2.0, 1e-12);
}

}  // namespace
}  // namespace clearsky::stress
