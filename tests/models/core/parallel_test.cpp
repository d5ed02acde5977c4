// parallel_for visits each index once and propagates exceptions.
#include "models/core/parallel.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace clearsky {
namespace {

TEST(ParallelFor, VisitsEveryIndexExactlyOnce) {
  std::vector<std::atomic<int>> visits(1000);
  parallel_for(
      visits.size(), [&](std::size_t i) { visits[i]++; }, 4, 7);
  for (const auto& v : visits) EXPECT_EQ(v.load(), 1);
}

TEST(ParallelFor, RethrowsTheFirstException) {
  EXPECT_THROW(parallel_for(
                   100,
                   [](std::size_t i) {
                     if (i == 42) throw std::runtime_error("x");
                   },
                   3),
               std::runtime_error);
}

}  // namespace
}  // namespace clearsky
