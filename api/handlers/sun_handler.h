// The sun query, transport-free (keys in the order below): parse the place and time
// (api/request/place_time.h), compute the position and the day's sunrise/transit/sunset with
// SPA, encode the answer (GET /v1/sun and `clearsky sun --json`):
//   {"zenith": DEG, "azimuth": DEG, "sunrise": ISO|null, "transit": ISO, "sunset": ISO|null,
//    "day": "normal"|"polar_day"|"polar_night", "delta_t_s": S,
//    "delta_t_source": "espenak_meeus"|"given"}
// zenith topocentric (refraction applied unless refraction=false), azimuth clockwise from North,
// times ISO 8601 in the request's UTC offset, null in polar day or night; delta_t_s the TT - UT1
// SPA used, computed from the time (models/solar/delta_t.h) unless the request gave delta_t.
#pragma once

#include <nlohmann/json.hpp>

#include "api/request/parameters.h"
#include "api/request/place_time.h"
#include "models/solar/solar_position.h"

namespace clearsky::api {

struct SunAnswer {
  SolarPosition position;
  SunTimes times;
};

// The place and time of a sun query: every parameter of the place/time table and no other
// (400 naming the first unknown one). now_unix_s is the instant taken when time is absent.
PlaceTime parse_sun_query(Parameters& parameters, double now_unix_s);
// SPA's refusals are ApiError naming the request parameter.
SunAnswer compute_sun(const PlaceTime& request);
nlohmann::ordered_json sun_answer_to_json(const PlaceTime& request, const SunAnswer& answer);
// parse_sun_query, compute_sun and sun_answer_to_json; errors are ApiError.
nlohmann::ordered_json handle_sun(Parameters& parameters, double now_unix_s);

// "normal", "polar_day" or "polar_night".
const char* day_kind_name(DayKind kind);

}  // namespace clearsky::api
