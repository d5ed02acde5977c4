// The sun request (GET /v1/sun, `clearsky sun`): place and time, and the atmosphere of SPA's
// refraction, parsed from text parameters into a validated SolarPositionInput.
//
// clang-format off
// | parameter   | unit    | default          | range                  | meaning                         |
// |-------------|---------|------------------|------------------------|---------------------------------|
// | lat         | degree  | required         | [-90, 90]              | decimal or DMS, North positive  |
// | lon         | degree  | required         | [-180, 180]            | decimal or DMS, East positive   |
// | time        | ISO 8601| now (UTC)        | years 0000-6000        | with offset or Z                |
// | altitude    | m       | 0                | >= -6500000            | above sea level                 |
// | pressure    | mbar    | 1013.25          | [0, 5000]              | annual mean, for refraction     |
// | temperature | Celsius | 15               | (-273, 6000]           | annual mean, for refraction     |
// | delta_t     | s       | 69               | [-8000, 8000]          | TT - UT1                        |
// | delta_ut1   | s       | 0                | (-1, 1)                | UT1 - UTC                       |
// | refraction  | bool    | true             | true/false             | apply atmospheric refraction    |
// clang-format on
//
// Answers carry times in the request's UTC offset. Errors are api::InvalidParameter naming the
// parameter.
#pragma once

#include <string>

#include "api/parse/query_parameters.h"
#include "models/solar/solar_position.h"

namespace clearsky::api {

struct SunRequest {
  SolarPositionInput position;
  int utc_offset_min = 0;      // of the request's time; the local day of sunrise/sunset
  bool utc_designator = true;  // the time was given with Z (or defaulted to now)
};

// now_unix_s is the instant used when no time is given.
SunRequest parse_sun_request(const QueryParameters& parameters, double now_unix_s);

}  // namespace clearsky::api
