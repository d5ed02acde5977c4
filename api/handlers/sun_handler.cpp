// GET /v1/sun: the sun's topocentric zenith and azimuth (degrees, azimuth clockwise from North)
// for lat, lon and time (NREL SPA, models/solar), and sunrise, transit and sunset of the local
// day of the given time, written with the time's UTC offset (null in polar day or night).
#include "api/handlers/handlers.h"
#include "api/request/place_time.h"

namespace clearsky::api {

ApiResponse get_sun(const ApiContext&, const ApiRequest& request) {
  Parameters p = request_parameters(request);
  const PlaceAndTime place = parse_place_and_time(p);
  p.reject_unused();
  const SolarPosition position = solar_position_checked(place.spa_input);
  const SunTimes times = sun_times(place.spa_input, place.timezone_offset_h);
  const auto instant = [&](const std::optional<double>& t) {
    return t ? nlohmann::json(format_iso_time(*t, place.timezone_offset_h))
             : nlohmann::json(nullptr);
  };
  const char* day = times.day_kind == DayKind::polar_day     ? "polar_day"
                    : times.day_kind == DayKind::polar_night ? "polar_night"
                                                             : "normal";
  return json_response(
      {{"lat", place.spa_input.latitude_deg},
       {"lon", place.spa_input.longitude_deg},
       {"time", format_iso_time(place.spa_input.unix_time_utc_s, place.timezone_offset_h)},
       {"zenith_deg", finite(position.zenith_deg)},
       {"azimuth_deg", finite(position.azimuth_deg)},
       {"elevation_deg", finite(90.0 - position.zenith_deg)},
       {"refraction", place.spa_input.refraction},
       {"sunrise", instant(times.sunrise_utc_s)},
       {"transit", instant(times.transit_utc_s)},
       {"sunset", instant(times.sunset_utc_s)},
       {"day", day},
       {"algorithm", "NREL SPA (Reda and Andreas 2004)"}});
}

}  // namespace clearsky::api
