// The byte budget of answer buffers in flight (api/http/answer_memory_budget.h): reservations
// fit under the limit together, are refused beyond it, and are given back when released, also
// when many threads reserve at once.
#include "api/http/answer_memory_budget.h"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

namespace clearsky::api {
namespace {

TEST(AnswerMemoryBudget, ReservationsFitUnderTheLimitAndAreGivenBack) {
  AnswerMemoryBudget budget(1000);
  auto first = budget.try_reserve(600);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->bytes(), 600u);
  EXPECT_EQ(budget.reserved_bytes(), 600u);
  EXPECT_EQ(budget.try_reserve(401), nullptr);
  EXPECT_EQ(budget.reserved_bytes(), 600u);
  auto second = budget.try_reserve(400);
  ASSERT_NE(second, nullptr);
  EXPECT_EQ(budget.reserved_bytes(), 1000u);
  EXPECT_EQ(budget.try_reserve(1), nullptr);
  first.reset();
  EXPECT_EQ(budget.reserved_bytes(), 400u);
  EXPECT_NE(budget.try_reserve(600), nullptr);
  second.reset();
  EXPECT_EQ(budget.reserved_bytes(), 0u);
}

TEST(AnswerMemoryBudget, MoreThanTheWholeLimitIsNeverReserved) {
  AnswerMemoryBudget budget(1000);
  EXPECT_EQ(budget.try_reserve(1001), nullptr);
  EXPECT_EQ(budget.try_reserve(static_cast<std::size_t>(-1)), nullptr);
  EXPECT_EQ(budget.reserved_bytes(), 0u);
  EXPECT_NE(budget.try_reserve(1000), nullptr);
}

TEST(AnswerMemoryBudget, AReservationMayOutliveTheBudget) {
  std::shared_ptr<const AnswerMemoryBudget::Reservation> kept;
  {
    AnswerMemoryBudget budget(10);
    kept = budget.try_reserve(10);
    ASSERT_NE(kept, nullptr);
  }
  EXPECT_EQ(kept->bytes(), 10u);
  kept.reset();  // releases into the counter the reservation keeps alive
}

TEST(AnswerMemoryBudget, ConcurrentReservationsNeverExceedTheLimit) {
  constexpr std::size_t kLimit = 10;
  AnswerMemoryBudget budget(kLimit);
  std::atomic<bool> exceeded{false};
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t) {
    threads.emplace_back([&] {
      for (int i = 0; i < 2000; ++i) {
        auto reservation = budget.try_reserve(3);
        if (budget.reserved_bytes() > kLimit) exceeded = true;
      }
    });
  }
  for (auto& thread : threads) thread.join();
  EXPECT_FALSE(exceeded.load());
  EXPECT_EQ(budget.reserved_bytes(), 0u);
}

}  // namespace
}  // namespace clearsky::api
