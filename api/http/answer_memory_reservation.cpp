// Reserving an answer's bytes out of the answer memory budget (answer_memory_reservation.h).
#include "api/http/answer_memory_reservation.h"

#include "api/error/api_error.h"
#include "api/http/batch_answer_bytes.h"

namespace clearsky::api {

std::shared_ptr<const AnswerMemoryBudget::Reservation> reserve_answer_memory(
    const ApiContext& context, std::size_t bytes, const std::string& what,
    const std::string& smaller) {
  if (context.answer_memory == nullptr) return nullptr;
  AnswerMemoryBudget& budget = *context.answer_memory;
  if (bytes > budget.limit_bytes()) {
    throw too_large("answer_memory", what + " needs " + std::to_string(bytes) +
                                         " bytes in flight, above the answer memory budget of " +
                                         std::to_string(budget.limit_bytes()) + " bytes; " +
                                         smaller);
  }
  auto reservation = budget.try_reserve(bytes);
  if (!reservation) {
    throw ApiError(503, "busy", "answer_memory",
                   "answer_memory: " + what + " needs " + std::to_string(bytes) +
                       " bytes in flight and the answer memory budget of " +
                       std::to_string(budget.limit_bytes()) + " bytes is held by answers being " +
                       "sent (" + std::to_string(budget.reserved_bytes()) +
                       " bytes); try again later",
                   context.retry_after_s);
  }
  return reservation;
}

std::shared_ptr<const AnswerMemoryBudget::Reservation> reserve_batch_answer_memory(
    const ApiContext& context, std::size_t views, std::size_t grid_wavelengths,
    std::size_t numbers_per_view) {
  const std::size_t bytes = batch_answer_bytes(views, grid_wavelengths, numbers_per_view);
  if (bytes < kUncountedAnswerBytes) return nullptr;
  return reserve_answer_memory(context, bytes, "the answer of " + std::to_string(views) + " views",
                               "ask for fewer views or fewer wavelengths per request");
}

}  // namespace clearsky::api
