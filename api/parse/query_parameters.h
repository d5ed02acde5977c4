// Request parameters as name/value text pairs (the shape of an HTTP query string, and of
// httplib::Params, and what the CLI builds from its options), with the checks every request
// makes: a parameter given twice or one the request does not know is an error naming it.
#pragma once

#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace clearsky::api {

using QueryParameters = std::multimap<std::string, std::string>;

// The value of a parameter given at most once; empty when absent.
std::optional<std::string> optional_parameter(const QueryParameters& parameters,
                                              const std::string& name);
// The value of a parameter that must be given exactly once.
std::string required_parameter(const QueryParameters& parameters, const std::string& name);
// Throws InvalidParameter for the first parameter whose name is not in known.
void reject_unknown_parameters(const QueryParameters& parameters,
                               std::initializer_list<std::string_view> known);

}  // namespace clearsky::api
