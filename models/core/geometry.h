// Directions and positions of the sky queries. Angles in radians inside models/ (degrees only at
// the API edge); azimuth clockwise from North (docs/architecture.md "Conventions and units"),
// zenith from the local vertical. Local frame: x East, y North, z up.
#pragma once

#include <cmath>

#include "models/core/numeric.h"

namespace clearsky {

struct Vec3 {
  double x = 0, y = 0, z = 0;
  friend Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
};
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(Vec3 a) { return (1.0 / length(a)) * a; }

// A direction on the sky: zenith angle and azimuth (clockwise from North), radians.
struct SkyDirection {
  double zenith_rad = 0;
  double azimuth_rad = 0;

  Vec3 unit_vector() const {
    const double s = std::sin(zenith_rad);
    return {s * std::sin(azimuth_rad), s * std::cos(azimuth_rad), std::cos(zenith_rad)};
  }
  static SkyDirection from_unit_vector(Vec3 v) { return {safe_acos(v.z), std::atan2(v.x, v.y)}; }
};

using SunPosition = SkyDirection;
using ViewDirection = SkyDirection;

// Cosine of the angle between two sky directions (the scattering-angle cosine for a view and
// the sun, up to sign conventions stated where used).
inline double cos_angle_between(const SkyDirection& a, const SkyDirection& b) {
  return clamp_cosine(std::cos(a.zenith_rad) * std::cos(b.zenith_rad) +
                      std::sin(a.zenith_rad) * std::sin(b.zenith_rad) *
                          std::cos(a.azimuth_rad - b.azimuth_rad));
}

// Where the observer is: altitude above the ground sphere (m). Aerial perspective queries add
// a distance along the view (m); infinity means "to the end of the atmosphere or the ground".
struct Viewpoint {
  double altitude_m = 0;
};

}  // namespace clearsky
