// Writes an instant as ISO 8601 local time with its offset (iso8601_time.h); the civil date
// comes from std::chrono's calendar.
#include "api/encode/iso8601_time.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace clearsky::api {

std::string format_iso8601_time(double unix_time_utc_s, int utc_offset_min, bool utc_designator) {
  // 1e15 s (31 million years) keeps every intermediate within long long.
  if (!(std::abs(unix_time_utc_s) < 1e15) || std::abs(utc_offset_min) > 18 * 60) {
    throw std::invalid_argument(
        "format_iso8601_time: instant not finite or too far, or offset beyond 18 hours");
  }
  const long long local_s =
      std::llround(unix_time_utc_s) + 60LL * (utc_designator ? 0 : utc_offset_min);
  const long long days = (local_s >= 0 ? local_s : local_s - 86399) / 86400;
  const long long second_of_day = local_s - days * 86400;
  const std::chrono::year_month_day date{std::chrono::sys_days(std::chrono::days(days))};
  const int year = static_cast<int>(date.year());

  char buffer[64];
  const char* year_format = year >= 0 && year <= 9999 ? "%04d" : "%+05d";
  int n = std::snprintf(buffer, sizeof buffer, year_format, year);
  n += std::snprintf(buffer + n, sizeof buffer - n, "-%02u-%02uT%02lld:%02lld:%02lld",
                     static_cast<unsigned>(date.month()), static_cast<unsigned>(date.day()),
                     second_of_day / 3600, second_of_day / 60 % 60, second_of_day % 60);
  if (utc_designator) {
    std::snprintf(buffer + n, sizeof buffer - n, "Z");
  } else {
    const int magnitude = std::abs(utc_offset_min);
    std::snprintf(buffer + n, sizeof buffer - n, "%c%02d:%02d", utc_offset_min < 0 ? '-' : '+',
                  magnitude / 60, magnitude % 60);
  }
  return buffer;
}

}  // namespace clearsky::api
