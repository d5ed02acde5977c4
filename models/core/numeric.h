// Numerical guards shared by every model (docs/conventions.md "Numerical guards"): rounding error
// is absorbed, a real bug (an argument far outside the domain) trips an assertion in debug builds.
#pragma once

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace clearsky {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDegree = kPi / 180.0;  // radians per degree

constexpr double degrees_to_radians(double degrees) { return degrees * kDegree; }
constexpr double radians_to_degrees(double radians) { return radians / kDegree; }

// Clamps a cosine (or any dot product of unit vectors) into [-1, 1].
inline double clamp_cosine(double mu) {
  assert(!(std::abs(mu) > 1.0 + 1e-6) && "cosine far outside [-1, 1]");
  return std::clamp(mu, -1.0, 1.0);
}

// Square root of a quantity that is mathematically >= 0 but may round below it.
inline double safe_sqrt(double a) {
  assert(!(a < -1e-6 * (1.0 + std::abs(a))) && "safe_sqrt of a clearly negative value");
  return std::sqrt(std::max(a, 0.0));
}

// acos of a dot product of unit vectors.
inline double safe_acos(double mu) { return std::acos(clamp_cosine(mu)); }

// True for a finite value >= 0; false for NaN (validation written so that NaN fails it).
inline bool is_finite_non_negative(double x) { return std::isfinite(x) && x >= 0.0; }

}  // namespace clearsky
