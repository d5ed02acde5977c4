// The byte budget of answer buffers in flight (answer_memory_budget.h).
#include "api/http/answer_memory_budget.h"

namespace clearsky::api {

AnswerMemoryBudget::AnswerMemoryBudget(std::size_t limit_bytes)
    : counter_(std::make_shared<Counter>()) {
  counter_->limit_bytes = limit_bytes;
}

std::shared_ptr<const AnswerMemoryBudget::Reservation> AnswerMemoryBudget::try_reserve(
    std::size_t bytes) {
  std::size_t reserved = counter_->reserved_bytes.load();
  // Compare-and-swap: concurrent reservations never take the total above the limit together.
  do {
    if (bytes > counter_->limit_bytes || reserved > counter_->limit_bytes - bytes) return nullptr;
  } while (!counter_->reserved_bytes.compare_exchange_weak(reserved, reserved + bytes));
  return std::make_shared<const Reservation>(counter_, bytes);
}

}  // namespace clearsky::api
