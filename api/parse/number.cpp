// Strict numbers and booleans for request parameters (see number.h).
#include "api/parse/number.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

#include "api/parse/invalid_parameter.h"

namespace clearsky::api {
namespace {

std::string_view trim(std::string_view text) {
  const auto is_space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return text;
}

}  // namespace

double parse_number(std::string_view text, const std::string& parameter) {
  const std::string_view body = trim(text);
  // from_chars rejects a leading '+', which people write; skip one before a digit or '.'.
  std::string_view digits = body;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+')
    digits.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (body.empty() || error != std::errc{} || end != digits.data() + digits.size()) {
    throw InvalidParameter(parameter, "expected a number, got " + quoted(text));
  }
  if (!std::isfinite(value))
    throw InvalidParameter(parameter, "must be a finite number, got " + quoted(text));
  return value;
}

double parse_number_in_range(std::string_view text, const std::string& parameter, double lo,
                             double hi) {
  const double value = parse_number(text, parameter);
  if (!(value >= lo && value <= hi)) {
    std::ostringstream message;
    message << "must be in [" << lo << ", " << hi << "], got " << quoted(text);
    throw InvalidParameter(parameter, message.str());
  }
  return value;
}

bool parse_boolean(std::string_view text, const std::string& parameter) {
  std::string lower(trim(text));
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower == "true" || lower == "1" || lower == "yes") return true;
  if (lower == "false" || lower == "0" || lower == "no") return false;
  throw InvalidParameter(parameter, "expected true or false, got " + quoted(text));
}

}  // namespace clearsky::api
