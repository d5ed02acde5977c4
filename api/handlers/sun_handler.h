// The sun query, transport-free (keys in the order below): parse the parameters, compute the
// position and the day's sunrise/transit/sunset with SPA, encode the answer (GET /v1/sun and
// `clearsky sun --json`):
//   {"zenith": DEG, "azimuth": DEG, "sunrise": ISO|null, "transit": ISO, "sunset": ISO|null,
//    "day": "normal"|"polar_day"|"polar_night"}
// zenith topocentric (refraction applied unless refraction=false), azimuth clockwise from North,
// times ISO 8601 in the request's UTC offset, null in polar day or night.
#pragma once

#include <nlohmann/json.hpp>

#include "api/parse/query_parameters.h"
#include "api/parse/sun_request.h"
#include "models/solar/solar_position.h"

namespace clearsky::api {

struct SunAnswer {
  SolarPosition position;
  SunTimes times;
};

SunAnswer compute_sun(const SunRequest& request);
nlohmann::ordered_json sun_answer_to_json(const SunRequest& request, const SunAnswer& answer);
// parse_sun_request, compute_sun and sun_answer_to_json; throws InvalidParameter.
nlohmann::ordered_json handle_sun(const QueryParameters& parameters, double now_unix_s);

// "normal", "polar_day" or "polar_night".
const char* day_kind_name(DayKind kind);

}  // namespace clearsky::api
