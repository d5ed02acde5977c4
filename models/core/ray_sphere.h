// Distances along a ray to the spheres of a spherically symmetric atmosphere, in the
// (r, mu) parameterisation of Bruneton and Neyret 2008: r the distance of the ray origin to
// the planet centre, mu the cosine of the ray's zenith angle at the origin. A point at
// distance d along the ray is at radius sqrt(d^2 + 2 r mu d + r^2).
// Written to stay exact at grazing angles (the discriminant is formed as r^2 (mu^2 - 1) + R^2,
// not as a difference of large squares of distances) and for origins outside the sphere.
#pragma once

#include <cmath>
#include <limits>

#include "models/core/numeric.h"

namespace clearsky {

// Discriminant (per unit) of the ray/sphere equation d^2 + 2 r mu d + r^2 - R^2 = 0.
inline double ray_sphere_discriminant(double r, double mu, double sphere_radius) {
  return r * r * (mu * mu - 1.0) + sphere_radius * sphere_radius;
}

// Whether the ray hits the sphere of radius sphere_radius at a distance > 0, for an origin
// outside or on it (r >= R): it must point down and pass within R of the centre.
inline bool ray_hits_sphere_from_outside(double r, double mu, double sphere_radius) {
  return mu < 0.0 && ray_sphere_discriminant(r, mu, sphere_radius) >= 0.0;
}

// Distance to the first intersection with a sphere the origin is outside of (r >= R);
// infinity when the ray misses it.
inline double distance_to_sphere_from_outside(double r, double mu, double sphere_radius) {
  if (!ray_hits_sphere_from_outside(r, mu, sphere_radius))
    return std::numeric_limits<double>::infinity();
  return std::max(-r * mu - safe_sqrt(ray_sphere_discriminant(r, mu, sphere_radius)), 0.0);
}

// Distance to the exit of a sphere the origin is inside of (r <= R); always finite.
inline double distance_to_sphere_from_inside(double r, double mu, double sphere_radius) {
  return std::max(-r * mu + safe_sqrt(ray_sphere_discriminant(r, mu, sphere_radius)), 0.0);
}

// Radius and zenith cosine at distance d along the ray (r, mu).
inline double radius_at_distance(double r, double mu, double d) {
  return std::sqrt(d * d + 2.0 * r * mu * d + r * r);
}
inline double mu_at_distance(double r, double mu, double d) {
  const double r_d = radius_at_distance(r, mu, d);
  return r_d > 0.0 ? clamp_cosine((r * mu + d) / r_d) : 1.0;
}

// Segment of a ray inside the atmosphere shell [bottom, top]: from the entry distance (0 when
// the origin is inside) to where it reaches the ground or leaves through the top.
struct AtmosphereSegment {
  double start = 0;  // m
  double end = 0;    // m; start == end when the ray misses the atmosphere
  bool hits_ground = false;
};

inline AtmosphereSegment atmosphere_segment(double r, double mu, double bottom_radius,
                                            double top_radius) {
  AtmosphereSegment s;
  if (r > top_radius) {
    if (!ray_hits_sphere_from_outside(r, mu, top_radius)) return s;  // misses the atmosphere
    s.start = distance_to_sphere_from_outside(r, mu, top_radius);
  }
  const double ground = r >= bottom_radius ? distance_to_sphere_from_outside(r, mu, bottom_radius)
                                           : std::numeric_limits<double>::infinity();
  if (std::isfinite(ground)) {
    s.end = ground;
    s.hits_ground = true;
  } else if (r > top_radius) {
    s.end = s.start + 2.0 * safe_sqrt(ray_sphere_discriminant(r, mu, top_radius));
  } else {
    s.end = distance_to_sphere_from_inside(r, mu, top_radius);
  }
  return s;
}

}  // namespace clearsky
