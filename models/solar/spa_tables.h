// The published data tables of NREL's Solar Position Algorithm (Reda and Andreas 2004, NREL/TP-
// 560-34302): Table A4.2, the Earth periodic terms of the VSOP87 theory truncated by Meeus
// (heliocentric longitude L0..L5, latitude B0..B1, radius vector R0..R4), and Table A4.3, the
// periodic terms of the nutation in longitude and obliquity (IAU 1980 series, 63 terms).
#pragma once

#include <array>
#include <span>

namespace clearsky::spa {

// One term A cos(B + C tau) of a VSOP87 series; tau in Julian ephemeris millennia, B in radians,
// C in radians per millennium; A in 1e-8 radians (L, B) or 1e-8 astronomical units (R).
struct EarthPeriodicTerm {
  double a;
  double b;
  double c;
};

// The series L0..L5, B0..B1 and R0..R4 (eq. 9 to 12, 14 and 15 sum series i times tau^i).
const std::array<std::span<const EarthPeriodicTerm>, 6>& earth_longitude_series();
const std::array<std::span<const EarthPeriodicTerm>, 2>& earth_latitude_series();
const std::array<std::span<const EarthPeriodicTerm>, 5>& earth_radius_series();

// One nutation term: the multipliers Y0..Y4 of the fundamental arguments X0..X4 (mean
// elongation of the Moon from the Sun, mean anomaly of the Sun, mean anomaly of the Moon,
// argument of latitude of the Moon, longitude of the Moon's ascending node), and the
// coefficients of (a + b JCE) sin(sum) for longitude and (c + d JCE) cos(sum) for obliquity,
// in units of 0.0001 arc seconds (eq. 20 to 22).
struct NutationTerm {
  std::array<int, 5> y;
  double a;
  double b;
  double c;
  double d;
};

std::span<const NutationTerm> nutation_terms();

}  // namespace clearsky::spa
