// Latitude and longitude from decimal or DMS text through GeographicLib::DMS (coordinates.h).
#include "api/parse/coordinates.h"

#include <GeographicLib/Constants.hpp>
#include <GeographicLib/DMS.hpp>
#include <cmath>

#include "api/error/api_error.h"

namespace clearsky::api {
namespace {

using GeographicLib::DMS;

std::string quoted(std::string_view text) { return '"' + std::string(text) + '"'; }

// GeographicLib 2.1 (Debian 12) reads a ':' that follows a seconds component (4"1:1, or a
// fourth colon) as a fourth component and writes past its 3-element arrays: the process
// crashes (found by fuzz/coordinates_fuzz.cpp). The colon notation is D:M or D:M:S, so text
// with a colon is handed over only in that form: at most two colons, and besides them only
// digits, a decimal point, signs, spaces and hemisphere letters (no d, ', " or their
// Unicode forms, which it would count as components too).
bool safe_for_dms(std::string_view text) {
  if (text.find(':') == std::string_view::npos) return true;
  int colons = 0;
  for (const char c : text) {
    if (c == ':') {
      ++colons;
    } else if (!((c >= '0' && c <= '9') || c == '.' || c == '+' || c == '-' || c == ' ' ||
                 std::string_view("NSEWnsew").find(c) != std::string_view::npos)) {
      return false;
    }
  }
  return colons <= 2;
}

double decode_angle(std::string_view text, const std::string& parameter, DMS::flag wanted,
                    double limit_deg) {
  const std::string shown = quoted(text);
  DMS::flag hemisphere = DMS::NONE;
  double degrees = 0.0;
  if (!safe_for_dms(text))
    throw invalid_parameter(parameter, "expected decimal degrees or degrees-minutes-seconds, got " +
                                           shown + " (the colon form is D:M or D:M:S)");
  try {
    degrees = DMS::Decode(std::string(text), hemisphere);
  } catch (const GeographicLib::GeographicErr& e) {
    throw invalid_parameter(parameter, "expected decimal degrees or degrees-minutes-seconds, got " +
                                           shown + " (" + e.what() + ")");
  }
  if (hemisphere != DMS::NONE && hemisphere != wanted) {
    throw invalid_parameter(parameter,
                            std::string("the hemisphere of ") + shown + " belongs to a " +
                                (wanted == DMS::LATITUDE ? "longitude (E/W)" : "latitude (N/S)"));
  }
  if (!std::isfinite(degrees))
    throw invalid_parameter(parameter, "must be a finite angle, got " + shown);
  if (!(std::abs(degrees) <= limit_deg)) {
    const std::string range = limit_deg == 90.0 ? "[-90, 90]" : "[-180, 180]";
    throw invalid_parameter(parameter, "must be in " + range + " degrees, got " + shown);
  }
  return degrees;
}

}  // namespace

double parse_latitude(std::string_view text, const std::string& parameter) {
  return decode_angle(text, parameter, DMS::LATITUDE, 90.0);
}

double parse_longitude(std::string_view text, const std::string& parameter) {
  return decode_angle(text, parameter, DMS::LONGITUDE, 180.0);
}

}  // namespace clearsky::api
