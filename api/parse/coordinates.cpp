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

double decode_angle(std::string_view text, const std::string& parameter, DMS::flag wanted,
                    double limit_deg) {
  const std::string shown = quoted(text);
  DMS::flag hemisphere = DMS::NONE;
  double degrees = 0.0;
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
