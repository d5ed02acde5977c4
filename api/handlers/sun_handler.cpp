// The sun query from parameters to JSON (sun_handler.h).
#include "api/handlers/sun_handler.h"

#include "api/encode/iso8601_time.h"
#include "api/error/api_error.h"
#include "models/core/invalid_input.h"

namespace clearsky::api {

PlaceTime parse_sun_query(Parameters& parameters, double now_unix_s) {
  const PlaceTime request = parse_place_and_time(parameters, now_unix_s);
  parameters.reject_unused();
  return request;
}

SunAnswer compute_sun(const PlaceTime& request) {
  try {
    return SunAnswer{solar_position(request.position),
                     sun_times(request.position, request.utc_offset_min / 60.0)};
  } catch (const InvalidInput& e) {
    throw from_invalid_input(e);
  }
}

const char* day_kind_name(DayKind kind) {
  switch (kind) {
    case DayKind::polar_day:
      return "polar_day";
    case DayKind::polar_night:
      return "polar_night";
    case DayKind::normal:
      break;
  }
  return "normal";
}

nlohmann::ordered_json sun_answer_to_json(const PlaceTime& request, const SunAnswer& answer) {
  const auto time_or_null = [&](const std::optional<double>& unix_s) -> nlohmann::ordered_json {
    if (!unix_s) return nullptr;
    return format_iso8601_time(*unix_s, request.utc_offset_min, request.utc_designator);
  };
  return nlohmann::ordered_json{
      {"zenith", answer.position.zenith_deg},
      {"azimuth", answer.position.azimuth_deg},
      {"sunrise", time_or_null(answer.times.sunrise_utc_s)},
      {"transit", time_or_null(answer.times.transit_utc_s)},
      {"sunset", time_or_null(answer.times.sunset_utc_s)},
      {"day", day_kind_name(answer.times.day_kind)},
      {"delta_t_s", request.position.delta_t_s},
      {"delta_t_source", request.delta_t_from_time ? "espenak_meeus" : "given"},
  };
}

nlohmann::ordered_json handle_sun(Parameters& parameters, double now_unix_s) {
  const PlaceTime request = parse_sun_query(parameters, now_unix_s);
  return sun_answer_to_json(request, compute_sun(request));
}

}  // namespace clearsky::api
