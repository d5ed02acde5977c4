// Reading the members of the server's JSON answers: a missing or mistyped member becomes
// Error with code "invalid_answer" (the answer is not what /openapi.json describes), and a
// null member an empty optional.
//
// Thread-safety: pure functions.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "clearsky/client/error.h"
#include "clearsky/client/sky_types.h"

namespace clearsky::client::detail {

// Parses an answer's body (status: the answer's, for the Error).
nlohmann::json parse_answer(const std::string& body, int status);

template <typename T>
T member(const nlohmann::json& object, const char* name) {
  const auto it = object.find(name);
  if (it == object.end() || it->is_null())
    throw Error(0, "invalid_answer", std::string("the answer has no member ") + name);
  try {
    return it->get<T>();
  } catch (const nlohmann::json::exception& e) {
    throw Error(0, "invalid_answer", std::string("member ") + name + ": " + e.what());
  }
}

template <typename T>
std::optional<T> optional_member(const nlohmann::json& object, const char* name) {
  const auto it = object.find(name);
  if (it == object.end() || it->is_null()) return std::nullopt;
  return member<T>(object, name);
}

// Parameters as JSON (numbers and texts) and back.
nlohmann::json parameters_json(const Parameters& parameters);
Parameters parameters_of(const nlohmann::json& object);

}  // namespace clearsky::client::detail
