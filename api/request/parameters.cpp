// Typed access to request parameters, with strict parsing and unused-parameter detection.
#include "api/request/parameters.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "api/error/api_error.h"
#include "api/error/utf8_text.h"

namespace clearsky::api {

namespace {

std::string format_limit(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

std::string_view trim(std::string_view s) {
  const auto is_space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::string lower_case(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

}  // namespace

double number_value(std::string_view parameter, std::string_view text) {
  text = trim(text);
  // from_chars rejects a leading '+', which people write; skip one before a digit or '.' only
  // (so that "+-1" and "++1" stay errors).
  std::string_view digits = text;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+')
    digits.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (text.empty() || error != std::errc() || end != digits.data() + digits.size()) {
    throw invalid_parameter(std::string(parameter), "'" + std::string(text) + "' is not a number");
  }
  if (!std::isfinite(value))
    throw invalid_parameter(std::string(parameter), "must be a finite number");
  return value;
}

void Parameters::add(const std::string& name, std::string value) {
  // Every value a handler reads is text it may quote, store or send back: refused here unless
  // it is UTF-8, so that no handler meets other bytes (docs/request-parsing.md).
  if (!is_valid_utf8(name))
    throw invalid_parameter(name,
                            "a parameter name must be UTF-8 (percent-encoded bytes included)");
  if (!is_valid_utf8(value))
    throw invalid_parameter(name, "the value is not UTF-8 (percent-encoded bytes included)");
  if (!values_.emplace(name, Value{std::move(value)}).second) {
    throw ApiError::about(400, "duplicate_parameter", name, "given more than once");
  }
}

Parameters Parameters::from_json_object(std::string endpoint, const nlohmann::json& object,
                                        std::initializer_list<std::string_view> structured) {
  if (!object.is_object())
    throw ApiError::about(400, "invalid_body", "body", "must be a JSON object");
  Parameters p(std::move(endpoint));
  for (const auto& [name, value] : object.items()) {
    bool skip = false;
    for (std::string_view s : structured) skip = skip || s == name;
    if (skip) continue;
    if (value.is_string()) {
      p.add(name, value.get<std::string>());
    } else if (value.is_boolean()) {
      p.add(name, value.get<bool>() ? "true" : "false");
    } else if (value.is_number()) {
      std::ostringstream out;
      out.precision(17);
      out << value.get<double>();
      p.add(name, out.str());
    } else {
      throw invalid_parameter(name, "must be a string, a number or a boolean");
    }
  }
  return p;
}

bool Parameters::has_any(std::initializer_list<std::string_view> names) const {
  for (std::string_view n : names)
    if (values_.contains(n)) return true;
  return false;
}

const std::string* Parameters::read(std::string_view name) {
  const auto it = values_.find(name);
  if (it == values_.end()) return nullptr;
  it->second.used = true;
  return &it->second.text;
}

std::optional<std::string> Parameters::text(std::string_view name) {
  const std::string* value = read(name);
  if (value == nullptr) return std::nullopt;
  return *value;
}

std::string Parameters::required_text(std::string_view name) {
  auto value = text(name);
  if (!value) throw missing_parameter(std::string(name));
  return *value;
}

std::optional<double> Parameters::number(std::string_view name, double min, double max) {
  const std::string* value = read(name);
  if (value == nullptr) return std::nullopt;
  const double x = number_value(name, *value);
  if (!(x >= min && x <= max)) {
    throw invalid_parameter(std::string(name),
                            "must be in [" + format_limit(min) + ", " + format_limit(max) + "]");
  }
  return x;
}

double Parameters::number_or(std::string_view name, double fallback, double min, double max) {
  return number(name, min, max).value_or(fallback);
}

double Parameters::required_number(std::string_view name, double min, double max) {
  const auto x = number(name, min, max);
  if (!x) throw missing_parameter(std::string(name));
  return *x;
}

std::optional<long long> Parameters::integer(std::string_view name, long long min, long long max) {
  const auto value = text(name);
  if (!value) return std::nullopt;
  const std::string_view t = trim(*value);
  long long x = 0;
  const auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), x);
  if (t.empty() || error != std::errc() || end != t.data() + t.size()) {
    throw invalid_parameter(std::string(name), "'" + *value + "' is not an integer");
  }
  if (x < min || x > max) {
    throw invalid_parameter(
        std::string(name), "must be in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
  }
  return x;
}

std::string Parameters::choice(std::string_view name,
                               std::initializer_list<std::string_view> choices,
                               std::string_view fallback) {
  const auto value = text(name);
  if (!value) return std::string(fallback);
  std::string list;
  for (std::string_view c : choices) {
    if (c == *value) return *value;
    list += (list.empty() ? "" : ", ") + std::string(c);
  }
  throw invalid_parameter(std::string(name), "'" + *value + "' is not one of " + list);
}

bool Parameters::boolean_or(std::string_view name, bool fallback) {
  const auto value = text(name);
  if (!value) return fallback;
  const std::string word = lower_case(trim(*value));
  if (word == "true" || word == "1" || word == "yes") return true;
  if (word == "false" || word == "0" || word == "no") return false;
  throw invalid_parameter(std::string(name), "must be true or false");
}

void Parameters::reject_unused() const {
  for (const auto& [name, value] : values_) {
    if (!value.used) throw unknown_parameter(name, endpoint_);
  }
}

}  // namespace clearsky::api
