// Solar position from place and time: NREL's Solar Position Algorithm (Reda and Andreas 2004,
// "Solar position algorithm for solar radiation applications", Solar Energy 76(5), NREL/TP-560-
// 34302), uncertainty +-0.0003 degrees for years -2000..6000, with atmospheric refraction from
// pressure and temperature, and delta-T (TT - UT) as an input.
//
// | input              | unit     | range            | meaning                                      |
// |--------------------|----------|------------------|----------------------------------------------|
// | unix_time_utc_s    | s        | years -2000..6000| UTC instant, seconds since 1970-01-01T00:00Z  |
// | latitude_deg       | degree   | [-90, 90]        | geodetic, North positive                     |
// | longitude_deg      | degree   | [-180, 180]      | East positive                                |
// | elevation_m        | m        | >= -6500000      | observer elevation above sea level           |
// | pressure_mbar      | millibar | [0, 5000]        | annual mean local pressure (refraction)      |
// | temperature_c      | Celsius  | [-273, 6000]     | annual mean local temperature (refraction)   |
// | delta_t_s          | s        | [-8000, 8000]    | TT - UT1                                      |
// | delta_ut1_s        | s        | (-1, 1)          | UT1 - UTC                                     |
// | refraction         | -        | bool             | apply refraction to the topocentric zenith   |
//
// Output: topocentric zenith (degrees from the vertical, refraction applied when asked) and
// azimuth (degrees clockwise from North, 0..360), and sunrise/transit/sunset of the local day.
#pragma once

#include <optional>

namespace clearsky {

struct SolarPositionInput {
  double unix_time_utc_s = 0;
  double latitude_deg = 0;
  double longitude_deg = 0;
  double elevation_m = 0;
  double pressure_mbar = 1013.25;
  double temperature_c = 15.0;
  double delta_t_s = 69.0;
  double delta_ut1_s = 0.0;
  bool refraction = true;
  double atmospheric_refraction_at_horizon_deg = 0.5667;
};

struct SolarPosition {
  double zenith_deg = 0;   // topocentric
  double azimuth_deg = 0;  // clockwise from North
  double declination_deg = 0;
  double hour_angle_deg = 0;
  double equation_of_time_min = 0;
};

struct SunTimes {
  // UTC instants (unix seconds); empty in polar day or night.
  std::optional<double> sunrise_utc_s;
  std::optional<double> transit_utc_s;
  std::optional<double> sunset_utc_s;
};

// Throws std::invalid_argument naming the first invalid input (NaN fails).
SolarPosition solar_position(const SolarPositionInput& input);
// Sunrise, sun transit and sunset (SPA appendix A.2) of the UTC day containing the input time,
// shifted by timezone_offset_h to define the local day.
SunTimes sun_times(const SolarPositionInput& input, double timezone_offset_h);

}  // namespace clearsky
