// Formatting of capture times (measured_sky.h).
#include "models/evaluation/measured_sky.h"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <stdexcept>

namespace clearsky {

std::string local_time_iso8601(double unix_time_utc_s, int utc_offset_minutes) {
  if (!std::isfinite(unix_time_utc_s)) throw std::invalid_argument("capture time is not finite");
  const std::time_t local =
      static_cast<std::time_t>(std::floor(unix_time_utc_s)) + std::time_t{utc_offset_minutes} * 60;
  std::tm parts{};
  if (gmtime_r(&local, &parts) == nullptr) throw std::invalid_argument("capture time out of range");
  const int offset = utc_offset_minutes < 0 ? -utc_offset_minutes : utc_offset_minutes;
  char text[96];
  std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d%c%02d:%02d", parts.tm_year + 1900,
                parts.tm_mon + 1, parts.tm_mday, parts.tm_hour, parts.tm_min, parts.tm_sec,
                utc_offset_minutes < 0 ? '-' : '+', offset / 60, offset % 60);
  return text;
}

}  // namespace clearsky
