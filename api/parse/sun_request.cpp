// Parsing of the sun request (sun_request.h): each parameter by its parser, then the whole
// input through SPA's own validation, whose messages are mapped back to parameter names.
#include "api/parse/sun_request.h"

#include <stdexcept>
#include <string_view>
#include <utility>

#include "api/parse/coordinates.h"
#include "api/parse/invalid_parameter.h"
#include "api/parse/iso8601_time.h"
#include "api/parse/number.h"

namespace clearsky::api {
namespace {

// SolarPositionInput field -> request parameter.
constexpr std::pair<std::string_view, std::string_view> kFieldParameters[] = {
    {"unix_time_utc_s", "time"}, {"latitude_deg", "lat"},       {"longitude_deg", "lon"},
    {"elevation_m", "altitude"}, {"pressure_mbar", "pressure"}, {"temperature_c", "temperature"},
    {"delta_t_s", "delta_t"},    {"delta_ut1_s", "delta_ut1"},
};

double number_or(const QueryParameters& parameters, const std::string& name, double fallback) {
  const auto text = optional_parameter(parameters, name);
  return text ? parse_number(*text, name) : fallback;
}

// Re-throws SPA's std::invalid_argument ("<field>: <why>") as InvalidParameter of the request
// parameter the field came from.
[[noreturn]] void rethrow_as_parameter(const std::invalid_argument& error) {
  const std::string_view what = error.what();
  for (const auto& [field, parameter] : kFieldParameters) {
    if (what.rfind(std::string(field) + ": ", 0) == 0) {
      if (parameter == "time")
        throw InvalidParameter("time", "must lie in the years -2000 to 6000 (SPA's range)");
      throw InvalidParameter(std::string(parameter), std::string(what.substr(field.size() + 2)));
    }
  }
  throw InvalidParameter("request", std::string(what));
}

}  // namespace

SunRequest parse_sun_request(const QueryParameters& parameters, double now_unix_s) {
  reject_unknown_parameters(parameters, {"lat", "lon", "time", "altitude", "pressure",
                                         "temperature", "delta_t", "delta_ut1", "refraction"});
  SunRequest request;
  SolarPositionInput& in = request.position;
  in.latitude_deg = parse_latitude(required_parameter(parameters, "lat"), "lat");
  in.longitude_deg = parse_longitude(required_parameter(parameters, "lon"), "lon");
  if (const auto time = optional_parameter(parameters, "time")) {
    const Iso8601Time parsed = parse_iso8601_time(*time, "time");
    in.unix_time_utc_s = parsed.unix_time_utc_s;
    request.utc_offset_min = parsed.utc_offset_min;
    request.utc_designator = parsed.utc_designator;
  } else {
    in.unix_time_utc_s = now_unix_s;
  }
  in.elevation_m = number_or(parameters, "altitude", 0.0);
  in.pressure_mbar = number_or(parameters, "pressure", 1013.25);
  in.temperature_c = number_or(parameters, "temperature", 15.0);
  in.delta_t_s = number_or(parameters, "delta_t", 69.0);
  in.delta_ut1_s = number_or(parameters, "delta_ut1", 0.0);
  if (const auto refraction = optional_parameter(parameters, "refraction")) {
    in.refraction = parse_boolean(*refraction, "refraction");
  }
  try {
    validate_solar_position_input(in);
  } catch (const std::invalid_argument& error) {
    rethrow_as_parameter(error);
  }
  return request;
}

}  // namespace clearsky::api
