// Place and time of a request (lat, lon, altitude, time, and SPA's optional atmosphere inputs
// pressure, temperature, delta_t) turned into the input of NREL's SPA (models/solar).
//
// | parameter   | unit     | range        | default | meaning                                   |
// |-------------|----------|--------------|---------|-------------------------------------------|
// | lat         | degree   | [-90, 90]    | -       | decimal degrees or DMS (40d26'46"N)        |
// | lon         | degree   | [-180, 180]  | -       | decimal degrees or DMS, East positive     |
// | time        | ISO 8601 | years -2000..6000 | -  | with offset (2013-05-27T11:45:00-04:00) or Z
// | | altitude    | m        | [-500, 1e7]  | 0       | observer elevation (also the viewpoint)   |
// | pressure    | mbar     | [0, 5000]    | 1013.25 | annual mean pressure (refraction)         |
// | temperature | Celsius  | [-273, 6000] | 15      | annual mean temperature (refraction)      |
// | delta_t     | s        | [-8000, 8000]| 69      | TT - UT1                                  |
// | refraction  | bool     |              | true    | apply atmospheric refraction              |
#pragma once

#include <string>

#include "api/request/parameters.h"
#include "models/solar/solar_position.h"

namespace clearsky::api {

struct IsoTime {
  double unix_time_utc_s = 0;
  double offset_h = 0;  // the UTC offset written in the text
};
// "2013-05-27T11:45:00-04:00", "...Z", "...+0530"; seconds and fractions optional; an offset
// is required. 400 naming parameter otherwise.
IsoTime parse_iso_time(const std::string& parameter, const std::string& text);
// The instant as ISO 8601 in the given offset, to the second.
std::string format_iso_time(double unix_time_utc_s, double offset_h);

struct PlaceAndTime {
  SolarPositionInput spa_input;
  double timezone_offset_h = 0;  // of the given time, for the local day of sunrise/sunset
};

// Reads lat, lon and time (required) and the optional SPA inputs; altitude is read without
// being consumed (the viewpoint reads it). 400 naming the parameter on any invalid value.
PlaceAndTime parse_place_and_time(Parameters& p);
// solar_position() with its std::invalid_argument turned into a 400 naming the request
// parameter (time, lat, lon, altitude, ...).
SolarPosition solar_position_checked(const SolarPositionInput& input);

}  // namespace clearsky::api
