// ISO 8601 durations of a request, as exact seconds: "PT1H", "PT10M", "PT30S", "PT1H30M",
// "P1D", "P1DT12H" (ISO 8601-1:2019 section 5.5.2.4, the designators D, H, M and S with
// non-negative integer values; years, months and weeks, whose length varies or is rarely
// used for steps, and fractions are refused). Errors are api::ApiError (400 invalid_parameter)
// naming the parameter.
#pragma once

#include <string>
#include <string_view>

namespace clearsky::api {

// The duration in seconds (> 0; a zero duration is refused).
long long parse_iso8601_duration_s(std::string_view text, const std::string& parameter);

}  // namespace clearsky::api
