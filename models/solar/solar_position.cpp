// Solar position and sunrise/transit/sunset by NREL's SPA (Reda and Andreas 2004): input
// validation, the composition of the steps of spa_functions.h (section 3) and appendix A.2.
#include "models/solar/solar_position.h"

#include <GeographicLib/Math.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "models/core/invalid_input.h"
#include "models/core/numeric.h"
#include "models/solar/spa_functions.h"

namespace clearsky {
namespace {

using GeographicLib::Math;

constexpr double kSecondsPerDay = 86400.0;
// Apparent radius of the sun's disk used by SPA for sunrise and sunset and for the refraction
// cut-off (degrees).
constexpr double kSunRadiusDeg = 0.26667;
// Unix seconds of 0h UT of -2000-01-01 (Julian calendar, JD 990557.5) and of 6001-01-01
// (Gregorian, JD 3912880.5): the years SPA is valid for.
constexpr double kEarliestUnixS = (990557.5 - 2440587.5) * kSecondsPerDay;
constexpr double kLatestUnixS = (3912880.5 - 2440587.5) * kSecondsPerDay;

void require(bool ok, const char* name, double value, const char* range) {
  if (ok) return;
  std::ostringstream reason;
  reason.precision(10);
  reason << "must be " << range << ", got " << value;
  throw InvalidInput(name, reason.str());
}

bool within(double value, double lo, double hi) { return value >= lo && value <= hi; }

void validate_input(const SolarPositionInput& in) {
  require(within(in.unix_time_utc_s, kEarliestUnixS, kLatestUnixS), "unix_time_utc_s",
          in.unix_time_utc_s, "an instant of the years -2000 to 6000");
  require(within(in.latitude_deg, -90.0, 90.0), "latitude_deg", in.latitude_deg,
          "in [-90, 90] degrees");
  require(within(in.longitude_deg, -180.0, 180.0), "longitude_deg", in.longitude_deg,
          "in [-180, 180] degrees");
  require(std::isfinite(in.elevation_m) && in.elevation_m >= -6500000.0, "elevation_m",
          in.elevation_m, "finite and >= -6500000 m");
  require(within(in.pressure_mbar, 0.0, 5000.0), "pressure_mbar", in.pressure_mbar,
          "in [0, 5000] mbar");
  require(in.temperature_c > -273.0 && in.temperature_c <= 6000.0, "temperature_c",
          in.temperature_c, "in (-273, 6000] Celsius");
  require(within(in.delta_t_s, -8000.0, 8000.0), "delta_t_s", in.delta_t_s, "in [-8000, 8000] s");
  require(in.delta_ut1_s > -1.0 && in.delta_ut1_s < 1.0, "delta_ut1_s", in.delta_ut1_s,
          "in (-1, 1) s");
  require(within(in.atmospheric_refraction_at_horizon_deg, -5.0, 5.0),
          "atmospheric_refraction_at_horizon_deg", in.atmospheric_refraction_at_horizon_deg,
          "in [-5, 5] degrees");
}

// Days since J2000.0 (UT) of a unix instant; computed from the difference rather than through
// the Julian day so that no precision is lost to the large offset.
double days_since_j2000(double unix_s) {
  return (unix_s - spa::kJ2000UnixSeconds) / kSecondsPerDay;
}

// Fractional part in [0, 1).
double fraction_of_day(double x) {
  const double f = x - std::floor(x);
  return f >= 1.0 ? 0.0 : f;
}

// Interpolation of the sun's right ascension or declination at n days from 0h TT of the day,
// from its values a day before, on and a day after (eq. A9, A10). Day-to-day differences are
// wrapped into [-180, 180): for right ascension this is SPA's intent on the day it passes 360
// degrees, where the report's literal rule (reduce a difference above 2 to [0, 1)) drifts.
double interpolate_three_days(const std::array<double, 3>& v, double n, bool is_angle_on_circle) {
  double a = v[1] - v[0];
  double b = v[2] - v[1];
  if (is_angle_on_circle) {
    a = spa::wrap_degrees_180(a);
    b = spa::wrap_degrees_180(b);
  }
  const double c = b - a;
  return v[1] + n * (a + b + c * n) / 2.0;
}

}  // namespace

void validate_solar_position_input(const SolarPositionInput& input) { validate_input(input); }

SolarPosition solar_position(const SolarPositionInput& input) {
  validate_input(input);
  const spa::TimeScales t = spa::time_scales(
      days_since_j2000(input.unix_time_utc_s + input.delta_ut1_s), input.delta_t_s);
  const spa::GeocentricSun sun = spa::geocentric_sun(t);
  const double sidereal_deg = spa::apparent_sidereal_time_deg(
      t.julian_day, t.julian_century, sun.nutation_longitude_deg, sun.true_obliquity_deg);
  // Observer local hour angle H (eq. 32).
  const double hour_angle_deg =
      spa::wrap_degrees_360(sidereal_deg + input.longitude_deg - sun.right_ascension_deg);
  const spa::TopocentricSun topo =
      spa::topocentric_sun(sun, hour_angle_deg, input.latitude_deg, input.elevation_m);
  const double e0_deg =
      spa::topocentric_elevation_deg(input.latitude_deg, topo.declination_deg, topo.hour_angle_deg);

  SolarPosition out;
  if (input.refraction &&
      e0_deg >= -(kSunRadiusDeg + input.atmospheric_refraction_at_horizon_deg)) {
    out.refraction_correction_deg =
        spa::refraction_correction_deg(e0_deg, input.pressure_mbar, input.temperature_c);
  }
  // Topocentric zenith (eq. 43, 44).
  out.zenith_deg = std::clamp(90.0 - (e0_deg + out.refraction_correction_deg), 0.0, 180.0);
  out.azimuth_deg =
      spa::topocentric_azimuth_deg(input.latitude_deg, topo.declination_deg, topo.hour_angle_deg);
  out.declination_deg = topo.declination_deg;
  out.hour_angle_deg = topo.hour_angle_deg;
  out.equation_of_time_min =
      spa::equation_of_time_min(t.julian_ephemeris_millennium, sun.right_ascension_deg,
                                sun.nutation_longitude_deg, sun.true_obliquity_deg);
  return out;
}

SunTimes sun_times(const SolarPositionInput& input, double timezone_offset_h) {
  validate_input(input);
  require(within(timezone_offset_h, -18.0, 18.0), "timezone_offset_h", timezone_offset_h,
          "in [-18, 18] hours");
  const double latitude = input.latitude_deg;
  const double longitude = input.longitude_deg;
  const double h0_prime_deg = -(kSunRadiusDeg + input.atmospheric_refraction_at_horizon_deg);

  // The local calendar day [local midnight, next local midnight) containing the input instant,
  // and the UT day of its local noon, whose 0h UT is SPA's reference (A.2.1). Relative to that
  // reference the local day spans fractions [window_start, window_start + 1) within [-0.5, 1.5).
  const double offset_s = timezone_offset_h * 3600.0;
  const double local_midnight_unix_s =
      std::floor((input.unix_time_utc_s + offset_s) / kSecondsPerDay) * kSecondsPerDay - offset_s;
  const double reference_unix_s =
      std::floor((local_midnight_unix_s + kSecondsPerDay / 2.0) / kSecondsPerDay) * kSecondsPerDay;
  const double window_start = (local_midnight_unix_s - reference_unix_s) / kSecondsPerDay;
  const double reference_days = days_since_j2000(reference_unix_s);

  // Apparent sidereal time at Greenwich at 0h UT (A.2.1), with the input delta-T.
  const spa::TimeScales t0 = spa::time_scales(reference_days, input.delta_t_s);
  const spa::GeocentricSun sun0 = spa::geocentric_sun(t0);
  const double nu_deg = spa::apparent_sidereal_time_deg(
      t0.julian_day, t0.julian_century, sun0.nutation_longitude_deg, sun0.true_obliquity_deg);

  // Geocentric right ascension and declination at 0h TT of the day before, the day and the
  // day after (A.2.2, delta-T = 0).
  std::array<double, 3> alpha{};
  std::array<double, 3> delta{};
  for (int i = 0; i < 3; ++i) {
    const spa::GeocentricSun sun =
        spa::geocentric_sun(spa::time_scales(reference_days + (i - 1), 0.0));
    alpha[i] = sun.right_ascension_deg;
    delta[i] = sun.declination_deg;
  }

  // Approximate transit time in fractions of the day (eq. A3) and the local hour angle at
  // sunrise and sunset (eq. A4). An argument outside [-1, 1] (or NaN at a pole) means that the
  // sun stays above (< -1) or below (> 1) the sunrise altitude all day.
  const double m0 = (alpha[1] - longitude - nu_deg) / 360.0;
  const double cos_h0 = (Math::sind(h0_prime_deg) - Math::sind(latitude) * Math::sind(delta[1])) /
                        (Math::cosd(latitude) * Math::cosd(delta[1]));
  SunTimes times;
  const bool rises_and_sets = std::abs(cos_h0) <= 1.0;
  if (!rises_and_sets) times.day_kind = cos_h0 < 0.0 ? DayKind::polar_day : DayKind::polar_night;
  const double h0_fraction = rises_and_sets ? radians_to_degrees(std::acos(cos_h0)) / 360.0 : 0.0;

  // Transit, sunrise, sunset (eq. A5, A6). Where SPA reduces each to [0, 1) of the reference UT
  // day, each is placed in the local day instead, so that all three belong to the local date
  // (SPA's reduction reports, west of Greenwich, the sunset of the previous evening: its
  // published 17:20:19 -07:00 for 2003-10-17 is the sunset of October 16).
  const auto in_local_day = [&](double m) {
    return window_start + fraction_of_day(m - window_start);
  };
  const std::array<double, 3> m = {in_local_day(m0), in_local_day(m0 - h0_fraction),
                                   in_local_day(m0 + h0_fraction)};
  // Each refined by interpolating the sun's position at its time (eq. A7 to A12) and correcting
  // the time (eq. A13 to A15).
  std::array<double, 3> event_fraction{};
  for (int i = 0; i < 3; ++i) {
    const double nu_i = nu_deg + 360.985647 * m[i];
    const double n = m[i] + input.delta_t_s / kSecondsPerDay;
    const double alpha_i = interpolate_three_days(alpha, n, true);
    const double delta_i = interpolate_three_days(delta, n, false);
    const double hour_angle_i = spa::wrap_degrees_180(nu_i + longitude - alpha_i);
    if (i == 0) {
      event_fraction[i] = m[i] - hour_angle_i / 360.0;
      continue;
    }
    const double altitude_i = radians_to_degrees(std::asin(
        clamp_cosine(Math::sind(latitude) * Math::sind(delta_i) +
                     Math::cosd(latitude) * Math::cosd(delta_i) * Math::cosd(hour_angle_i))));
    const double rate =
        360.0 * Math::cosd(delta_i) * Math::cosd(latitude) * Math::sind(hour_angle_i);
    // The correction is a Newton step on the altitude; the rate vanishes only where the sun
    // grazes the horizon at the meridian, where the first estimate is kept.
    event_fraction[i] = m[i] + (std::abs(rate) > 1e-12 ? (altitude_i - h0_prime_deg) / rate : 0.0);
  }

  times.transit_utc_s = reference_unix_s + kSecondsPerDay * event_fraction[0];
  if (rises_and_sets) {
    times.sunrise_utc_s = reference_unix_s + kSecondsPerDay * event_fraction[1];
    times.sunset_utc_s = reference_unix_s + kSecondsPerDay * event_fraction[2];
  }
  return times;
}

}  // namespace clearsky
