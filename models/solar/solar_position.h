// Solar position from place and time: NREL's Solar Position Algorithm (Reda and Andreas 2004,
// "Solar position algorithm for solar radiation applications", Solar Energy 76(5), NREL/TP-560-
// 34302), uncertainty +-0.0003 degrees for years -2000..6000, with atmospheric refraction from
// pressure and temperature, and delta-T (TT - UT) as an input.
//
// clang-format off
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
// | atmospheric_refraction_at_horizon_deg | degree | [-5, 5] | refraction at sunrise/sunset       |
// clang-format on
//
// Refraction (SPA eq. 42) is applied only when the unrefracted sun is above
// -(0.26667 + atmospheric_refraction_at_horizon_deg), i.e. when some of its disk can be seen.
// Unix time is continuous UTC without leap seconds; delta_ut1_s turns it into UT1 and delta_t_s
// into terrestrial time. Accepted instants are those of years -2000 to 6000, SPA's range.
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
  double zenith_deg = 0;            // topocentric, refraction applied when asked, [0, 180]
  double azimuth_deg = 0;           // clockwise from North, [0, 360)
  double declination_deg = 0;       // topocentric (delta', SPA eq. 39)
  double hour_angle_deg = 0;        // topocentric local hour angle (H', SPA eq. 40), [-180, 180)
  double equation_of_time_min = 0;  // apparent minus mean solar time (SPA eq. A2)
  double refraction_correction_deg = 0;  // delta e (SPA eq. 42), 0 when not applied
};

// Whether the sun crosses the horizon altitude -(0.26667 + refraction at horizon) that day.
enum class DayKind { normal, polar_day, polar_night };

struct SunTimes {
  // UTC instants (unix seconds). Sunrise and sunset are empty in polar day or night; the
  // transit (the sun's passage through the local meridian) exists every day.
  std::optional<double> sunrise_utc_s;
  std::optional<double> transit_utc_s;
  std::optional<double> sunset_utc_s;
  DayKind day_kind = DayKind::normal;
};

// Throws InvalidInput (models/core/invalid_input.h) naming the first invalid input field
// (the field name above); NaN fails every check.
SolarPosition solar_position(const SolarPositionInput& input);
// The checks solar_position and sun_times make, for callers that validate before computing.
void validate_solar_position_input(const SolarPositionInput& input);

// Sunrise, sun transit and sunset (SPA appendix A.2) of the local calendar day that contains
// the input instant, the local day being UTC shifted by timezone_offset_h (in [-18, 18] hours).
// SPA's interpolation over three days is kept; only its reduction of each event to the UT day
// is replaced by a placement in the local day, so that the three events are those of the local
// date (SPA's published sunset for its example is the one of the evening before; see the .cpp).
// A sunset after local midnight thus belongs to the next date, as it happens on it.
// Throws std::invalid_argument like solar_position, or naming timezone_offset_h.
SunTimes sun_times(const SolarPositionInput& input, double timezone_offset_h);

}  // namespace clearsky
