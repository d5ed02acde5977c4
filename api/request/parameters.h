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
  bool has(std::string_view name) const { return values_.contains(name); }
  // Whether any of the names is present (without marking them used).
  bool has_any(std::initializer_list<std::string_view> names) const;

  std::optional<std::string> text(std::string_view name);
  std::string required_text(std::string_view name);
  // A finite number in [min, max].
  std::optional<double> number(std::string_view name, double min, double max);
  double number_or(std::string_view name, double fallback, double min, double max);
  double required_number(std::string_view name, double min, double max);
  // An integer in [min, max].
  std::optional<long long> integer(std::string_view name, long long min, long long max);
  // One of choices; fallback when absent.
  std::string choice(std::string_view name, std::initializer_list<std::string_view> choices,
                     std::string_view fallback);
  // true/false (also 1/0 and yes/no, in any case).
  bool boolean_or(std::string_view name, bool fallback);

  // Throws a 400 naming the first parameter that was given but never read.
  void reject_unused() const;

 private:
  // A value and whether a handler has read it. Names are looked up as string_views
  // (std::less<>), so that reading a parameter by a literal name allocates nothing.
  struct Value {
    std::string text;
    bool used = false;
  };
  // The value named, marked used; nullptr when absent.
  const std::string* read(std::string_view name);

  std::string endpoint_;
  std::map<std::string, Value, std::less<>> values_;
};

// Strict number parsing for parameter values and list items (400 naming parameter).
double number_value(std::string_view parameter, std::string_view text);

}  // namespace clearsky::api
