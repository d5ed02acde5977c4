// Place and time through the parsers of api/parse, errors as ApiError.
#include "api/request/place_time.h"

#include "api/error/api_error.h"
#include "api/parse/coordinates.h"
#include "api/parse/invalid_parameter.h"
#include "api/parse/iso8601_time.h"

namespace clearsky::api {

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

SolarPositionInput parse_place_and_time(Parameters& p) {
  SolarPositionInput in;
  try {
    in.latitude_deg = parse_latitude(p.required_text("lat"), "lat");
    in.longitude_deg = parse_longitude(p.required_text("lon"), "lon");
    in.unix_time_utc_s = parse_iso8601_time(p.required_text("time"), "time").unix_time_utc_s;
  } catch (const InvalidParameter& e) {
    throw invalid_parameter(e.parameter(), e.message());
  }
  in.elevation_m = p.number_or("altitude", 0.0, -500.0, 1e7);
  in.pressure_mbar = p.number_or("pressure", in.pressure_mbar, 0.0, 5000.0);
  in.temperature_c = p.number_or("temperature", in.temperature_c, -273.0, 6000.0);
  in.delta_t_s = p.number_or("delta_t", in.delta_t_s, -8000.0, 8000.0);
  in.refraction = p.boolean_or("refraction", in.refraction);
  return in;
}

}  // namespace clearsky::api
