// The named parameters of one request (URL query or the scalar fields of a JSON body), read
// by handlers with typed, range-checked accessors that remember what was read, so that
// reject_unused() can name any parameter the request carried but the endpoint did not use
// (docs/conventions.md "Unknown parameters are refused"). The one parameter type of every
// endpoint and of the CLI, which builds one from its options (docs/request-parsing.md).
// Numbers are parsed strictly (the whole text, finite; NaN and infinity fail). Errors are
// ApiError naming the parameter. Not thread-safe: one instance per request.
#pragma once

#include <initializer_list>
#include <map>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace clearsky::api {

class Parameters {
 public:
  explicit Parameters(std::string endpoint) : endpoint_(std::move(endpoint)) {}

  // Adds a parameter; a name given twice, or a name or value that is not UTF-8, is a 400
  // naming it.
  void add(const std::string& name, std::string value);
  // The scalar members of a JSON object (strings, numbers, booleans); members named in
  // structured are skipped (the caller reads them); arrays/objects elsewhere are 400s.
  static Parameters from_json_object(std::string endpoint, const nlohmann::json& object,
                                     std::initializer_list<std::string_view> structured);

  const std::string& endpoint() const { return endpoint_; }
  bool has(const std::string& name) const { return values_.contains(name); }
  // Whether any of the names is present (without marking them used).
  bool has_any(std::initializer_list<std::string_view> names) const;

  std::optional<std::string> text(const std::string& name);
  std::string required_text(const std::string& name);
  // A finite number in [min, max].
  std::optional<double> number(const std::string& name, double min, double max);
  double number_or(const std::string& name, double fallback, double min, double max);
  double required_number(const std::string& name, double min, double max);
  // An integer in [min, max].
  std::optional<long long> integer(const std::string& name, long long min, long long max);
  // One of choices; fallback when absent.
  std::string choice(const std::string& name, std::initializer_list<std::string_view> choices,
                     std::string_view fallback);
  // true/false (also 1/0 and yes/no, in any case).
  bool boolean_or(const std::string& name, bool fallback);

  // Throws a 400 naming the first parameter that was given but never read.
  void reject_unused() const;

 private:
  std::string endpoint_;
  std::map<std::string, std::string> values_;
  std::set<std::string> used_;
};

// Strict number parsing for parameter values and list items (400 naming parameter).
double number_value(const std::string& parameter, std::string_view text);

}  // namespace clearsky::api
