// Latitude and longitude of a request, in decimal degrees ("42.443449", "-76.481962") or as
// degrees-minutes-seconds with an optional hemisphere (42d26'36.4"N, 76:28:55.1W, 76°28′55.1″W),
// decoded by GeographicLib::DMS. A hemisphere letter must fit the coordinate (N/S for a
// latitude, E/W for a longitude). Errors are api::ApiError (400) naming the parameter.
#pragma once

#include <string>
#include <string_view>

namespace clearsky::api {

// Geodetic latitude in degrees, North positive, in [-90, 90].
double parse_latitude(std::string_view text, const std::string& parameter = "lat");
// Longitude in degrees, East positive, in [-180, 180].
double parse_longitude(std::string_view text, const std::string& parameter = "lon");

}  // namespace clearsky::api
