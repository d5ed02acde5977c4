// Place (GeographicLib::DMS decodes decimal and DMS coordinates) and ISO 8601 time.
#include "api/request/place_time.h"

#include <GeographicLib/DMS.hpp>
#include <cmath>
#include <cstdio>

#include "api/error/api_error.h"

namespace clearsky::api {

namespace {

// Days from 1970-01-01 to a proleptic Gregorian date (era-based count of the civil calendar).
long long days_from_civil(long long y, unsigned m, unsigned d) {
  y -= m <= 2;
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const unsigned yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<long long>(doe) - 719468;
}

bool leap(long long y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

double coordinate(Parameters& p, const std::string& name, double limit,
                  GeographicLib::DMS::flag expected) {
  const std::string text = p.required_text(name);
  double value = 0;
  try {
    GeographicLib::DMS::flag found = GeographicLib::DMS::NONE;
    value = GeographicLib::DMS::Decode(text, found);
    if (found != GeographicLib::DMS::NONE && found != expected) {
      throw invalid_parameter(name, "the hemisphere letter does not fit a " +
                                        std::string(name == "lat" ? "latitude" : "longitude"));
    }
  } catch (const GeographicLib::GeographicErr& e) {
    throw invalid_parameter(name, "'" + text + "' is not a coordinate (" + e.what() + ")");
  }
  if (!(std::isfinite(value) && std::abs(value) <= limit)) {
    throw invalid_parameter(name, "must be in [-" + std::to_string(static_cast<int>(limit)) + ", " +
                                      std::to_string(static_cast<int>(limit)) + "] degrees");
  }
  return value;
}

}  // namespace

IsoTime parse_iso_time(const std::string& parameter, const std::string& text) {
  const auto fail = [&]() -> ApiError {
    return invalid_parameter(
        parameter,
        "'" + text +
            "' is not an ISO 8601 time with offset, e.g. 2013-05-27T11:45:00-04:00 or ...Z");
  };
  std::size_t i = 0;
  const auto digits = [&](std::size_t n) -> long long {
    if (i + n > text.size()) throw fail();
    long long v = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const char c = text[i + k];
      if (c < '0' || c > '9') throw fail();
      v = v * 10 + (c - '0');
    }
    i += n;
    return v;
  };
  const auto expect = [&](char c) {
    if (i >= text.size() || text[i] != c) throw fail();
    ++i;
  };
  long long sign = 1;
  if (i < text.size() && (text[i] == '-' || text[i] == '+')) sign = text[i++] == '-' ? -1 : 1;
  const long long year = sign * digits(4);
  expect('-');
  const long long month = digits(2);
  expect('-');
  const long long day = digits(2);
  if (i >= text.size() || (text[i] != 'T' && text[i] != 't' && text[i] != ' ')) throw fail();
  ++i;
  const long long hour = digits(2);
  expect(':');
  const long long minute = digits(2);
  double second = 0;
  if (i < text.size() && text[i] == ':') {
    ++i;
    second = static_cast<double>(digits(2));
    if (i < text.size() && (text[i] == '.' || text[i] == ',')) {
      ++i;
      double scale = 0.1;
      const std::size_t start = i;
      while (i < text.size() && text[i] >= '0' && text[i] <= '9') {
        second += scale * (text[i++] - '0');
        scale *= 0.1;
      }
      if (i == start) throw fail();
    }
  }
  double offset_h = 0;
  if (i < text.size() && (text[i] == 'Z' || text[i] == 'z')) {
    ++i;
  } else if (i < text.size() && (text[i] == '+' || text[i] == '-')) {
    const double s = text[i++] == '-' ? -1.0 : 1.0;
    const long long oh = digits(2);
    long long om = 0;
    if (i < text.size() && text[i] == ':') ++i;
    if (i < text.size()) om = digits(2);
    if (oh > 18 || om > 59) throw fail();
    offset_h = s * (static_cast<double>(oh) + static_cast<double>(om) / 60.0);
  } else {
    throw invalid_parameter(parameter, "'" + text + "' has no UTC offset (add Z or e.g. -04:00)");
  }
  if (i != text.size()) throw fail();
  static constexpr int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (month < 1 || month > 12 || day < 1 ||
      day > kDays[month - 1] + (month == 2 && leap(year) ? 1 : 0) || hour > 23 || minute > 59 ||
      second >= 61.0) {
    throw invalid_parameter(parameter, "'" + text + "' is not a valid date and time");
  }
  if (year < -2000 || year > 6000)
    throw invalid_parameter(parameter, "years -2000 to 6000 are supported (SPA)");
  const double local = static_cast<double>(days_from_civil(year, static_cast<unsigned>(month),
                                                           static_cast<unsigned>(day))) *
                           86400.0 +
                       static_cast<double>(hour * 3600 + minute * 60) + second;
  return {local - offset_h * 3600.0, offset_h};
}

std::string format_iso_time(double unix_time_utc_s, double offset_h) {
  const double local = std::floor(unix_time_utc_s + offset_h * 3600.0 + 0.5);
  long long days = static_cast<long long>(std::floor(local / 86400.0));
  long long secs = static_cast<long long>(local) - days * 86400;
  // Civil date from days since 1970-01-01 (inverse of days_from_civil).
  days += 719468;
  const long long era = (days >= 0 ? days : days - 146096) / 146097;
  const unsigned doe = static_cast<unsigned>(days - era * 146097);
  const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const unsigned mp = (5 * doy + 2) / 153;
  const unsigned d = doy - (153 * mp + 2) / 5 + 1;
  const unsigned m = mp < 10 ? mp + 3 : mp - 9;
  const long long y = static_cast<long long>(yoe) + era * 400 + (m <= 2);
  const int offset_min = static_cast<int>(std::lround(offset_h * 60.0));
  char buffer[128];
  if (offset_min == 0) {
    std::snprintf(buffer, sizeof buffer, "%04lld-%02u-%02uT%02lld:%02lld:%02lldZ", y, m, d,
                  secs / 3600, secs / 60 % 60, secs % 60);
  } else {
    const int a = std::abs(offset_min);
    std::snprintf(buffer, sizeof buffer, "%04lld-%02u-%02uT%02lld:%02lld:%02lld%c%02d:%02d", y, m,
                  d, secs / 3600, secs / 60 % 60, secs % 60, offset_min < 0 ? '-' : '+', a / 60,
                  a % 60);
  }
  return buffer;
}

SolarPosition solar_position_checked(const SolarPositionInput& input) {
  try {
    return solar_position(input);
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    static const std::pair<const char*, const char*> kNames[] = {
        {"unix_time_utc_s", "time"},   {"latitude_deg", "lat"},
        {"longitude_deg", "lon"},      {"elevation_m", "altitude"},
        {"pressure_mbar", "pressure"}, {"temperature_c", "temperature"},
        {"delta_t_s", "delta_t"}};
    for (const auto& [field, parameter] : kNames) {
      if (message.rfind(field, 0) == 0) throw invalid_parameter(parameter, message);
    }
    throw invalid_parameter("time", message);
  }
}

PlaceAndTime parse_place_and_time(Parameters& p) {
  PlaceAndTime out;
  SolarPositionInput& in = out.spa_input;
  in.latitude_deg = coordinate(p, "lat", 90.0, GeographicLib::DMS::LATITUDE);
  in.longitude_deg = coordinate(p, "lon", 180.0, GeographicLib::DMS::LONGITUDE);
  const IsoTime time = parse_iso_time("time", p.required_text("time"));
  in.unix_time_utc_s = time.unix_time_utc_s;
  out.timezone_offset_h = time.offset_h;
  in.elevation_m = p.number_or("altitude", 0.0, -500.0, 1e7);
  in.pressure_mbar = p.number_or("pressure", in.pressure_mbar, 0.0, 5000.0);
  in.temperature_c = p.number_or("temperature", in.temperature_c, -273.0, 6000.0);
  in.delta_t_s = p.number_or("delta_t", in.delta_t_s, -8000.0, 8000.0);
  in.refraction = p.boolean_or("refraction", in.refraction);
  return out;
}

}  // namespace clearsky::api
