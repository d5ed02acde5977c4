// The geometry of a view ray and the sun in a spherically symmetric atmosphere, and what a
// single-scattering integration along such a ray returns. Shared by every numerical model
// (Nishita93, O'Neal, Bruneton, ...) and by the reference integrator.
//
// Parameterisation (Bruneton and Neyret 2008): r the distance of the observer to the planet
// centre (m), mu the cosine of the view zenith angle, mu_s the cosine of the sun zenith
// angle, nu the cosine of the angle between the view and sun directions. A point at distance
// d along the view is at radius sqrt(d^2 + 2 r mu d + r^2), where the sun zenith cosine is
// (r mu_s + d nu) / radius.
#pragma once

#include <cmath>

#include "models/core/geometry.h"
#include "models/core/numeric.h"
#include "models/spectral/spectrum.h"

namespace clearsky {

struct RaySunGeometry {
  double r_m = 0;
  double mu = 1;
  double mu_s = 1;
  double nu = 1;

  // From the query types: observer at viewpoint.altitude_m above a ground sphere of radius
  // bottom_radius_m, looking along view, sun in direction sun.
  static RaySunGeometry from(double bottom_radius_m, const Viewpoint& viewpoint,
                             const ViewDirection& view, const SunPosition& sun) {
    return {bottom_radius_m + viewpoint.altitude_m, clamp_cosine(std::cos(view.zenith_rad)),
            clamp_cosine(std::cos(sun.zenith_rad)), cos_angle_between(view, sun)};
  }

  // Sun zenith cosine at a point at distance d_m along the view, of radius radius_m.
  double mu_s_at(double d_m, double radius_m) const {
    return radius_m > 0.0 ? clamp_cosine((r_m * mu_s + d_m * nu) / radius_m) : mu_s;
  }
};

// Light scattered towards the observer along a segment of the view ray, and the
// transmittance of that segment: what aerial perspective needs (the radiance of an object at
// the end of the segment reaches the observer as L_object * transmittance + radiance).
struct ScatteringAlongRay {
  Spectrum radiance;         // in-scattered spectral radiance, W/(m2.sr.nm)
  Spectrum transmittance;    // observer to the end of the segment, dimensionless
  double length_m = 0;       // length of the segment inside the atmosphere
  bool hits_ground = false;  // the segment ends on the ground
};

}  // namespace clearsky
