// Strict text-to-value conversions for request parameters: the whole text must be one value;
// NaN, infinities, empty text and trailing characters are errors naming the parameter.
#pragma once

#include <string>
#include <string_view>

namespace clearsky::api {

// A finite decimal number ("12", "-3.5", "1e3"); leading and trailing spaces are allowed.
double parse_number(std::string_view text, const std::string& parameter);
// A finite number in [lo, hi].
double parse_number_in_range(std::string_view text, const std::string& parameter, double lo,
                             double hi);
// "true"/"false", "1"/"0", "yes"/"no" (case-insensitive).
bool parse_boolean(std::string_view text, const std::string& parameter);

}  // namespace clearsky::api
