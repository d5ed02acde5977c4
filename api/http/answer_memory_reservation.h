// An answer's bytes out of the server's answer memory budget (answer_memory_budget.h,
// docs/threat-model.md "exhaust memory with answers or requests"), reserved before the answer is
// computed and held until it has been sent or its connection was cut: 413 naming answer_memory
// when the bytes alone are above the whole budget (the answer could never be given), 503 +
// Retry-After naming answer_memory while other answers hold the budget. Null when the server
// has no budget.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "api/http/answer_memory_budget.h"
#include "api/http/api_types.h"

namespace clearsky::api {

// what: the answer, for the messages ("the image", "the batch"); smaller: how to ask for less.
std::shared_ptr<const AnswerMemoryBudget::Reservation> reserve_answer_memory(
    const ApiContext& context, std::size_t bytes, const std::string& what,
    const std::string& smaller);

// A batch answer's estimated bytes (batch_answer_bytes.h), reserved as above; null (nothing
// reserved) below kUncountedAnswerBytes.
std::shared_ptr<const AnswerMemoryBudget::Reservation> reserve_batch_answer_memory(
    const ApiContext& context, std::size_t views, std::size_t grid_wavelengths,
    std::size_t numbers_per_view);

}  // namespace clearsky::api
