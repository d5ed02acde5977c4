// Place and time of a sky request (lat, lon, altitude, time, and SPA's optional atmosphere
// inputs) turned into the input of NREL's SPA (models/solar), with the parsers of api/parse
// (GeographicLib DMS coordinates, ISO 8601 times with offset).
//
// | parameter   | unit     | range        | default | meaning                                   |
// |-------------|----------|--------------|---------|-------------------------------------------|
// | lat         | degree   | [-90, 90]    | -       | decimal degrees or DMS (40d26'46"N)        |
// | lon         | degree   | [-180, 180]  | -       | decimal degrees or DMS, East positive     |
// | time        | ISO 8601 | years -2000..6000 | -  | with offset (2013-05-27T11:45:00-04:00) or Z |
// | altitude    | m        | [-500, 1e7]  | 0       | observer elevation (also the viewpoint)   |
// | pressure    | mbar     | [0, 5000]    | 1013.25 | annual mean pressure (refraction)         |
// | temperature | Celsius  | [-273, 6000] | 15      | annual mean temperature (refraction)      |
// | delta_t     | s        | [-8000, 8000]| 69      | TT - UT1                                  |
// | refraction  | bool     |              | true    | apply atmospheric refraction              |
#pragma once

#include "api/request/parameters.h"
#include "models/solar/solar_position.h"

namespace clearsky::api {

// Reads lat, lon and time (required here: a sky needs an instant) and the optional SPA
// inputs. 400 naming the parameter on any invalid value.
SolarPositionInput parse_place_and_time(Parameters& p);
// solar_position() with its std::invalid_argument turned into a 400 naming the request
// parameter (time, lat, lon, altitude, ...).
SolarPosition solar_position_checked(const SolarPositionInput& input);

}  // namespace clearsky::api
