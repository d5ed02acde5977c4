// Implementation of the SPA steps declared in spa_functions.h (Reda and Andreas 2004, section 3
// and appendix A.1); equation numbers are the report's.
#include "models/solar/spa_functions.h"

#include <GeographicLib/Math.hpp>

#include <algorithm>
#include <cmath>
#include <span>

#include "models/core/numeric.h"
#include "models/solar/spa_tables.h"

namespace clearsky::spa {
namespace {

using GeographicLib::Math;

constexpr double kDaysPerJulianCentury = 36525.0;
constexpr double kSecondsPerDay = 86400.0;

// Sum over the terms of one series of A cos(B + C tau) (eq. 9).
double series_sum(std::span<const EarthPeriodicTerm> terms, double jme) {
  double sum = 0.0;
  for (const EarthPeriodicTerm& term : terms) sum += term.a * std::cos(term.b + term.c * jme);
  return sum;
}

// (sum_i S_i tau^i) / 1e8 over the series S_0, S_1, ... (eq. 10 to 12), by Horner's rule.
template <std::size_t N>
double earth_value(const std::array<std::span<const EarthPeriodicTerm>, N>& series, double jme) {
  double value = 0.0;
  for (std::size_t i = N; i-- > 0;) value = value * jme + series_sum(series[i], jme);
  return value / 1e8;
}

double cubic(double c0, double c1, double c2, double c3, double x) { return ((c3 * x + c2) * x + c1) * x + c0; }

}  // namespace

double wrap_degrees_360(double degrees) {
  double wrapped = std::fmod(degrees, 360.0);
  if (wrapped < 0.0) wrapped += 360.0;
  // fmod of a tiny negative angle plus 360 may round to 360 itself.
  return wrapped >= 360.0 ? 0.0 : wrapped;
}

double wrap_degrees_180(double degrees) {
  double wrapped = wrap_degrees_360(degrees + 180.0) - 180.0;
  return wrapped;
}

TimeScales time_scales(double days_since_j2000_ut1, double delta_t_s) {
  TimeScales t{};
  t.julian_day = kJ2000JulianDay + days_since_j2000_ut1;
  t.julian_century = days_since_j2000_ut1 / kDaysPerJulianCentury;
  const double ephemeris_days_since_j2000 = days_since_j2000_ut1 + delta_t_s / kSecondsPerDay;
  t.julian_ephemeris_day = kJ2000JulianDay + ephemeris_days_since_j2000;
  t.julian_ephemeris_century = ephemeris_days_since_j2000 / kDaysPerJulianCentury;
  t.julian_ephemeris_millennium = t.julian_ephemeris_century / 10.0;
  return t;
}

HeliocentricEarth heliocentric_earth(double julian_ephemeris_millennium) {
  const double jme = julian_ephemeris_millennium;
  HeliocentricEarth earth{};
  earth.longitude_deg = wrap_degrees_360(radians_to_degrees(earth_value(earth_longitude_series(), jme)));
  earth.latitude_deg = radians_to_degrees(earth_value(earth_latitude_series(), jme));
  earth.radius_au = earth_value(earth_radius_series(), jme);
  return earth;
}

Nutation nutation(double julian_ephemeris_century) {
  const double jce = julian_ephemeris_century;
  // Fundamental arguments X0..X4 in degrees (eq. 15 to 19).
  const double x[5] = {
      cubic(297.85036, 445267.111480, -0.0019142, 1.0 / 189474.0, jce),
      cubic(357.52772, 35999.050340, -0.0001603, -1.0 / 300000.0, jce),
      cubic(134.96298, 477198.867398, 0.0086972, 1.0 / 56250.0, jce),
      cubic(93.27191, 483202.017538, -0.0036825, 1.0 / 327270.0, jce),
      cubic(125.04452, -1934.136261, 0.0020708, 1.0 / 450000.0, jce),
  };
  double longitude_sum = 0.0;
  double obliquity_sum = 0.0;
  for (const NutationTerm& term : nutation_terms()) {
    double argument_deg = 0.0;
    for (int j = 0; j < 5; ++j) argument_deg += x[j] * term.y[j];
    argument_deg = wrap_degrees_360(argument_deg);
    longitude_sum += (term.a + term.b * jce) * Math::sind(argument_deg);
    obliquity_sum += (term.c + term.d * jce) * Math::cosd(argument_deg);
  }
  // The coefficients are in 0.0001 arc seconds (eq. 22, 23).
  return Nutation{longitude_sum / 36000000.0, obliquity_sum / 36000000.0};
}

double true_obliquity_deg(double julian_ephemeris_millennium, double nutation_obliquity_deg) {
  static constexpr double kCoefficients[] = {84381.448, -4680.93, -1.55, 1999.25, -51.38, -249.67,
                                             -39.05,    7.12,     27.87, 5.79,    2.45};
  const double u = julian_ephemeris_millennium / 10.0;
  double mean_obliquity_arcsec = 0.0;
  for (std::size_t i = std::size(kCoefficients); i-- > 0;)
    mean_obliquity_arcsec = mean_obliquity_arcsec * u + kCoefficients[i];
  return mean_obliquity_arcsec / 3600.0 + nutation_obliquity_deg;
}

double aberration_correction_deg(double radius_au) { return -20.4898 / (3600.0 * radius_au); }

double apparent_sidereal_time_deg(double julian_day, double julian_century, double nutation_longitude_deg,
                                  double true_obliquity) {
  const double days = julian_day - kJ2000JulianDay;
  const double mean_deg = wrap_degrees_360(280.46061837 + 360.98564736629 * days) +
                          julian_century * julian_century * (0.000387933 - julian_century / 38710000.0);
  return wrap_degrees_360(mean_deg + nutation_longitude_deg * Math::cosd(true_obliquity));
}

GeocentricSun geocentric_sun(const TimeScales& t) {
  const HeliocentricEarth earth = heliocentric_earth(t.julian_ephemeris_millennium);
  const Nutation nut = nutation(t.julian_ephemeris_century);
  GeocentricSun sun{};
  sun.longitude_deg = wrap_degrees_360(earth.longitude_deg + 180.0);
  sun.latitude_deg = -earth.latitude_deg;
  sun.radius_au = earth.radius_au;
  sun.nutation_longitude_deg = nut.longitude_deg;
  sun.nutation_obliquity_deg = nut.obliquity_deg;
  sun.true_obliquity_deg = true_obliquity_deg(t.julian_ephemeris_millennium, nut.obliquity_deg);
  sun.apparent_longitude_deg =
      sun.longitude_deg + nut.longitude_deg + aberration_correction_deg(earth.radius_au);
  const double sin_lambda = Math::sind(sun.apparent_longitude_deg);
  const double cos_lambda = Math::cosd(sun.apparent_longitude_deg);
  const double sin_epsilon = Math::sind(sun.true_obliquity_deg);
  const double cos_epsilon = Math::cosd(sun.true_obliquity_deg);
  const double sin_beta = Math::sind(sun.latitude_deg);
  const double cos_beta = Math::cosd(sun.latitude_deg);
  // eq. 30 with tan(beta) written as sin/cos so that no division can blow up.
  sun.right_ascension_deg = wrap_degrees_360(
      Math::atan2d(sin_lambda * cos_epsilon * cos_beta - sin_beta * sin_epsilon, cos_lambda * cos_beta));
  sun.declination_deg =
      radians_to_degrees(std::asin(clamp_cosine(sin_beta * cos_epsilon + cos_beta * sin_epsilon * sin_lambda)));
  return sun;
}

TopocentricSun topocentric_sun(const GeocentricSun& sun, double hour_angle_deg, double latitude_deg,
                               double elevation_m) {
  // Equatorial horizontal parallax (eq. 33), flattening 1 - 0.99664719 and equatorial radius
  // 6378140 m of the report's Earth ellipsoid (eq. 34 to 36); u written with atan2 so that the
  // poles need no tan(90).
  constexpr double kAxisRatio = 0.99664719;
  constexpr double kEquatorialRadiusM = 6378140.0;
  const double xi_deg = 8.794 / (3600.0 * sun.radius_au);
  const double u_deg = Math::atan2d(kAxisRatio * Math::sind(latitude_deg), Math::cosd(latitude_deg));
  const double x = Math::cosd(u_deg) + elevation_m / kEquatorialRadiusM * Math::cosd(latitude_deg);
  const double y = kAxisRatio * Math::sind(u_deg) + elevation_m / kEquatorialRadiusM * Math::sind(latitude_deg);
  const double sin_xi = Math::sind(xi_deg);
  const double cos_delta = Math::cosd(sun.declination_deg);
  const double denominator = cos_delta - x * sin_xi * Math::cosd(hour_angle_deg);
  TopocentricSun topo{};
  topo.right_ascension_parallax_deg = Math::atan2d(-x * sin_xi * Math::sind(hour_angle_deg), denominator);
  topo.right_ascension_deg = wrap_degrees_360(sun.right_ascension_deg + topo.right_ascension_parallax_deg);
  topo.declination_deg = Math::atan2d(
      (Math::sind(sun.declination_deg) - y * sin_xi) * Math::cosd(topo.right_ascension_parallax_deg), denominator);
  topo.hour_angle_deg = wrap_degrees_180(hour_angle_deg - topo.right_ascension_parallax_deg);
  return topo;
}

double topocentric_elevation_deg(double latitude_deg, double topocentric_declination_deg,
                                 double topocentric_hour_angle_deg) {
  const double sin_e0 = Math::sind(latitude_deg) * Math::sind(topocentric_declination_deg) +
                        Math::cosd(latitude_deg) * Math::cosd(topocentric_declination_deg) *
                            Math::cosd(topocentric_hour_angle_deg);
  return radians_to_degrees(std::asin(clamp_cosine(sin_e0)));
}

double refraction_correction_deg(double elevation_deg, double pressure_mbar, double temperature_c) {
  return (pressure_mbar / 1010.0) * (283.0 / (273.0 + temperature_c)) * 1.02 /
         (60.0 * Math::tand(elevation_deg + 10.3 / (elevation_deg + 5.11)));
}

double topocentric_azimuth_deg(double latitude_deg, double topocentric_declination_deg,
                               double topocentric_hour_angle_deg) {
  // eq. 45 multiplied through by cos(delta') > 0, so that no tangent is taken.
  const double cos_delta = Math::cosd(topocentric_declination_deg);
  const double gamma_deg = Math::atan2d(
      Math::sind(topocentric_hour_angle_deg) * cos_delta,
      Math::cosd(topocentric_hour_angle_deg) * Math::sind(latitude_deg) * cos_delta -
          Math::sind(topocentric_declination_deg) * Math::cosd(latitude_deg));
  return wrap_degrees_360(gamma_deg + 180.0);
}

double equation_of_time_min(double julian_ephemeris_millennium, double right_ascension_deg,
                            double nutation_longitude_deg, double true_obliquity) {
  const double jme = julian_ephemeris_millennium;
  const double mean_longitude_deg =
      280.4664567 +
      jme * (360007.6982779 + jme * (0.03032028 + jme * (1.0 / 49931.0 + jme * (-1.0 / 15300.0 - jme / 2000000.0))));
  const double e_deg = wrap_degrees_180(mean_longitude_deg - 0.0057183 - right_ascension_deg +
                                        nutation_longitude_deg * Math::cosd(true_obliquity));
  // 4 minutes of time per degree of hour angle (eq. A2).
  return 4.0 * e_deg;
}

}  // namespace clearsky::spa
