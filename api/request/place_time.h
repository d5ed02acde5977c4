// Place and time of a request, one parser for GET /v1/sun, every sky endpoint (lat, lon, time
// instead of sun_zenith and sun_azimuth) and `clearsky sun`: the input of NREL's SPA
// (models/solar), with GeographicLib DMS coordinates (api/parse/coordinates.h) and ISO 8601
// times with offset (api/parse/iso8601_time.h). The table below is place_time_parameters();
// tests/api/request/place_time_table_test.cpp reads this comment and compares the two.
//
// clang-format off
// | parameter   | unit     | default   | range           | meaning                                                 |
// |-------------|----------|-----------|-----------------|---------------------------------------------------------|
// | lat         | degree   | required  | [-90, 90]       | latitude, North positive: decimal or DMS (42d26'36"N)   |
// | lon         | degree   | required  | [-180, 180]     | longitude, East positive: decimal or DMS (76d28'55"W)   |
// | time        | ISO 8601 | now       | years [0, 6000] | instant with offset or Z (2013-05-27T11:45:00-04:00)    |
// | altitude    | m        | 0         | [-500, 1e7]     | observer above sea level (also the sky's viewpoint)     |
// | pressure    | mbar     | 1013.25   | [0, 5000]       | annual mean local pressure, for refraction              |
// | temperature | Celsius  | 15        | (-273, 6000]    | annual mean local temperature, for refraction           |
// | delta_t     | s        | from time | [-8000, 8000]   | TT - UT1; absent: Espenak-Meeus for the year            |
// | delta_ut1   | s        | 0         | (-1, 1)         | UT1 - UTC                                               |
// | refraction  | bool     | true      | true/false      | apply atmospheric refraction to the zenith              |
// clang-format on
//
// delta_t defaults to Delta T of the request's year and month by the Espenak-Meeus expressions
// (models/solar/delta_t.h); for a year after 3000, where none is published, a request without
// delta_t is refused naming delta_t. The value used is PlaceTime::position.delta_t_s, and
// delta_t_from_time says whether it was computed.
// time defaults to now on GET /v1/sun and `clearsky sun`; the sky endpoints require it (a GET
// answer there is cacheable, so it must not depend on the clock). Years are those of the
// instant in UTC; SPA itself covers -2000 to 6000, the ISO 8601 parser
// years 0000-9999. Every refusal is an ApiError (400) naming the parameter; the ranges lie within
// SPA's own checks, which solar_position_checked maps back to these names all the same.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "api/request/parameters.h"
#include "models/solar/solar_position.h"

namespace clearsky::api {

// A closed, open or half-open interval of numbers.
struct Interval {
  double min = 0;
  double max = 0;
  bool min_open = false;
  bool max_open = false;

  bool contains(double x) const {
    return (min_open ? x > min : x >= min) && (max_open ? x < max : x <= max);
  }
  // "[-500, 10000000]", "(-1, 1)".
  std::string text() const;
};

enum class PlaceTimeKind { latitude, longitude, time, number, boolean };

// One row of the table above.
struct PlaceTimeParameter {
  std::string_view name;
  PlaceTimeKind kind;
  std::string_view unit;
  // "required", "now" (time), or the default value as a request would write it.
  std::string_view fallback;
  // The accepted values; for time the calendar years (UTC); unused for a boolean.
  Interval range;
  std::string_view meaning;
  // The SPA input it sets (refraction, the one boolean, sets SolarPositionInput::refraction).
  double SolarPositionInput::*field = nullptr;
};

// The table, in its order.
std::span<const PlaceTimeParameter> place_time_parameters();

struct PlaceTime {
  SolarPositionInput position;
  int utc_offset_min = 0;          // of the request's time; the local day of sunrise/sunset
  bool utc_designator = true;      // the time was given with Z (or defaulted to now)
  bool delta_t_from_time = false;  // position.delta_t_s computed (Espenak-Meeus), not given
};

// The current instant, seconds since 1970-01-01T00:00:00Z (the default of time).
double current_unix_time_s();

// Reads every parameter of the table (marking them used). now_unix_s is the instant taken when
// time is absent; without it (the sky endpoints, whose GET answers are cacheable) time is
// required.
PlaceTime parse_place_and_time(Parameters& p, std::optional<double> now_unix_s);
// altitude alone, by its row of the table (the viewpoint of a sky given by sun_zenith).
double parse_altitude_m(Parameters& p);
// solar_position() with its InvalidInput turned into a 400 naming the request parameter.
SolarPosition solar_position_checked(const SolarPositionInput& input);

}  // namespace clearsky::api
