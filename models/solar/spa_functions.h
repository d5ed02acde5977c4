// The steps of NREL's Solar Position Algorithm (Reda and Andreas 2004, NREL/TP-560-34302,
// section 3 and appendix A) as pure functions, each citing its equations. solar_position.cpp
// composes them; the tests check each against the intermediate values the report publishes for
// its example (2003-10-17 12:30:30 -07:00, Golden, Colorado).
//
// Angles are in degrees throughout, as in the report; trigonometry goes through GeographicLib's
// degree functions (exact reduction of large angles such as the sidereal time).
#pragma once

namespace clearsky::spa {

// Unix seconds of the J2000.0 epoch, JD 2451545.0 = 2000-01-01T12:00:00 UT.
inline constexpr double kJ2000UnixSeconds = 946728000.0;
inline constexpr double kJ2000JulianDay = 2451545.0;

// Angle reduced to [0, 360).
double wrap_degrees_360(double degrees);
// Angle reduced to [-180, 180).
double wrap_degrees_180(double degrees);

// Section 3.1: the time scales of a UT1 instant (days since J2000.0 in UT) and delta-T = TT - UT.
struct TimeScales {
  double julian_day;                    // JD (eq. 4), UT
  double julian_century;                // JC (eq. 5)
  double julian_ephemeris_day;          // JDE (eq. 6), TT
  double julian_ephemeris_century;      // JCE (eq. 7)
  double julian_ephemeris_millennium;   // JME (eq. 8)
};
TimeScales time_scales(double days_since_j2000_ut1, double delta_t_s);

// Section 3.2: Earth heliocentric longitude L and latitude B (degrees) and radius vector R
// (astronomical units) from the periodic terms (eq. 9 to 12).
struct HeliocentricEarth {
  double longitude_deg;  // L, [0, 360)
  double latitude_deg;   // B
  double radius_au;      // R
};
HeliocentricEarth heliocentric_earth(double julian_ephemeris_millennium);

// Section 3.4: nutation in longitude (delta psi) and obliquity (delta epsilon), eq. 15 to 23.
struct Nutation {
  double longitude_deg;
  double obliquity_deg;
};
Nutation nutation(double julian_ephemeris_century);

// Section 3.5: true obliquity of the ecliptic epsilon = epsilon0 / 3600 + delta epsilon, with the
// mean obliquity epsilon0 in arc seconds by Laskar's polynomial in U = JME / 10 (eq. 24, 25).
double true_obliquity_deg(double julian_ephemeris_millennium, double nutation_obliquity_deg);

// Section 3.6: aberration correction delta tau = -20.4898 / (3600 R) degrees (eq. 26).
double aberration_correction_deg(double radius_au);

// Section 3.8: apparent sidereal time at Greenwich nu = nu0 + delta psi cos(epsilon), with the
// mean sidereal time nu0 of the UT Julian day and century (eq. 28, 29); [0, 360).
double apparent_sidereal_time_deg(double julian_day, double julian_century, double nutation_longitude_deg,
                                  double true_obliquity_deg);

// Sections 3.3, 3.7, 3.9 and 3.10: the geocentric apparent position of the sun.
struct GeocentricSun {
  double longitude_deg;           // Theta = L + 180 (eq. 13), [0, 360)
  double latitude_deg;            // beta = -B (eq. 14)
  double radius_au;               // R
  double apparent_longitude_deg;  // lambda = Theta + delta psi + delta tau (eq. 27)
  double nutation_longitude_deg;  // delta psi
  double nutation_obliquity_deg;  // delta epsilon
  double true_obliquity_deg;      // epsilon
  double right_ascension_deg;     // alpha (eq. 30), [0, 360)
  double declination_deg;         // delta (eq. 31)
};
GeocentricSun geocentric_sun(const TimeScales& t);

// Section 3.12 and 3.13: parallax in the sun's right ascension (eq. 33 to 38), topocentric
// declination (eq. 39) and topocentric local hour angle (eq. 40), from the observer's geodetic
// latitude and elevation above sea level and the geocentric local hour angle H (eq. 32).
struct TopocentricSun {
  double right_ascension_parallax_deg;  // delta alpha
  double right_ascension_deg;           // alpha'
  double declination_deg;               // delta'
  double hour_angle_deg;                // H', [-180, 180)
};
TopocentricSun topocentric_sun(const GeocentricSun& sun, double hour_angle_deg, double latitude_deg,
                               double elevation_m);

// Section 3.14: topocentric elevation angle without refraction e0 (eq. 41).
double topocentric_elevation_deg(double latitude_deg, double topocentric_declination_deg,
                                 double topocentric_hour_angle_deg);
// Atmospheric refraction correction delta e (eq. 42), for an annual mean local pressure and
// temperature; the caller decides whether the sun is high enough for it to apply.
double refraction_correction_deg(double elevation_deg, double pressure_mbar, double temperature_c);

// Section 3.15: topocentric azimuth, clockwise from North (eq. 45, 46), [0, 360).
double topocentric_azimuth_deg(double latitude_deg, double topocentric_declination_deg,
                               double topocentric_hour_angle_deg);

// Appendix A.1: the equation of time E in minutes (apparent minus mean solar time), from the
// sun's mean longitude M (eq. A1) and the geocentric right ascension; within [-20, 20] minutes.
double equation_of_time_min(double julian_ephemeris_millennium, double right_ascension_deg,
                            double nutation_longitude_deg, double true_obliquity_deg);

}  // namespace clearsky::spa
