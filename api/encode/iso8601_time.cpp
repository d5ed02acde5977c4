// Writes an instant as ISO 8601 local time with its offset (iso8601_time.h): the civil date
// and time of day are date's, the zones date/tz's.
#include "api/encode/iso8601_time.h"

#include <date/date.h>
#include <date/tz.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace clearsky::api {
namespace {

constexpr int kMaxUtcOffsetMin = 14 * 60;
// 28,500 years either side of 1970: within date::year's range (-32767 to 32767).
constexpr double kMaxAbsUnixTimeS = 9e11;

date::sys_seconds nearest_second(double unix_time_utc_s) {
  return date::sys_seconds(std::chrono::seconds(std::llround(unix_time_utc_s)));
}

const date::time_zone& zone_named(std::string_view zone) {
  try {
    return *date::locate_zone(zone);
  } catch (const std::exception& e) {
    throw std::invalid_argument("unknown time zone \"" + std::string(zone) + "\": " + e.what());
  }
}

}  // namespace

std::string format_iso8601_time(double unix_time_utc_s, int utc_offset_min, bool utc_designator) {
  if (!(std::abs(unix_time_utc_s) < kMaxAbsUnixTimeS) ||
      std::abs(utc_offset_min) > kMaxUtcOffsetMin) {
    throw std::invalid_argument(
        "format_iso8601_time: instant not finite or too far, or offset beyond 14 hours");
  }
  const int offset_min = utc_designator ? 0 : utc_offset_min;
  const date::local_seconds local(nearest_second(unix_time_utc_s).time_since_epoch() +
                                  std::chrono::minutes(offset_min));
  const int year = static_cast<int>(date::year_month_day(date::floor<date::days>(local)).year());

  char year_text[16];
  std::snprintf(year_text, sizeof year_text, year >= 0 && year <= 9999 ? "%04d" : "%+05d", year);
  std::string out = year_text + date::format("-%m-%dT%T", local);
  if (utc_designator) {
    out += 'Z';
  } else {
    const int magnitude = std::abs(offset_min);
    char offset_text[16];
    std::snprintf(offset_text, sizeof offset_text, "%c%02d:%02d", offset_min < 0 ? '-' : '+',
                  magnitude / 60, magnitude % 60);
    out += offset_text;
  }
  return out;
}

int utc_offset_min_in_zone(double unix_time_utc_s, std::string_view zone) {
  if (!(std::abs(unix_time_utc_s) < kMaxAbsUnixTimeS)) {
    throw std::invalid_argument("utc_offset_min_in_zone: instant not finite or too far");
  }
  const date::sys_info info = zone_named(zone).get_info(nearest_second(unix_time_utc_s));
  // Whole minutes (local mean times before standard time had offsets with seconds).
  return static_cast<int>(info.offset.count() / 60);
}

std::string format_iso8601_time_in_zone(double unix_time_utc_s, std::string_view zone) {
  return format_iso8601_time(unix_time_utc_s, utc_offset_min_in_zone(unix_time_utc_s, zone));
}

}  // namespace clearsky::api
