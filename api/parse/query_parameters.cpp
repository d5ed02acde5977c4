// Presence, uniqueness and known-name checks of request parameters (query_parameters.h).
#include "api/parse/query_parameters.h"

#include <algorithm>

#include "api/parse/invalid_parameter.h"

namespace clearsky::api {

std::optional<std::string> optional_parameter(const QueryParameters& parameters,
                                              const std::string& name) {
  const auto [first, last] = parameters.equal_range(name);
  if (first == last) return std::nullopt;
  if (std::next(first) != last) throw InvalidParameter(name, "given more than once");
  return first->second;
}

std::string required_parameter(const QueryParameters& parameters, const std::string& name) {
  std::optional<std::string> value = optional_parameter(parameters, name);
  if (!value) throw InvalidParameter(name, "is required");
  return *value;
}

void reject_unknown_parameters(const QueryParameters& parameters,
                               std::initializer_list<std::string_view> known) {
  for (const auto& [name, value] : parameters) {
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::string list;
      for (std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
      throw InvalidParameter(name, "unknown parameter (known: " + list + ")");
    }
  }
}

}  // namespace clearsky::api
