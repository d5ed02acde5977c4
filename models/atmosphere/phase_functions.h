// Phase functions (1/sr), normalised so that their integral over the sphere is 1.
// mu is the cosine of the scattering angle (angle between the incident propagation direction
// and the scattered direction; mu = 1 is forward scattering).
#pragma once

#include "models/core/numeric.h"

namespace clearsky {

// Rayleigh: 3/(16 pi) (1 + mu^2).
inline double rayleigh_phase(double mu) { return 3.0 / (16.0 * kPi) * (1.0 + mu * mu); }

// Cornette and Shanks 1992: 3/(8 pi) (1 - g^2)/(2 + g^2) (1 + mu^2)/(1 + g^2 - 2 g mu)^(3/2).
// The denominator is > 0 for |g| < 1 (validated by AtmosphereParameters).
inline double cornette_shanks_phase(double mu, double g) {
  const double g2 = g * g;
  const double denominator = 1.0 + g2 - 2.0 * g * mu;
  return 3.0 / (8.0 * kPi) * (1.0 - g2) / (2.0 + g2) * (1.0 + mu * mu) /
         (denominator * safe_sqrt(denominator));
}

// Isotropic: 1/(4 pi) (Haber's choice for Rayleigh and for orders >= 3).
inline double isotropic_phase() { return 1.0 / (4.0 * kPi); }

}  // namespace clearsky
