// The slow double-precision reference of single scattering along a view ray, which the fast paths
// of the numerical models (Nishita93's tables, O'Neal's Chapman approximation, Bruneton's 4D
// tables) are tested against (docs/conventions.md "Fast paths against slow references").
//
//   L = E_sun  integral over the view segment of
//         T(x, x_d) T_sun(x_d) [beta_R rho_R(h) P_R(nu) + beta_M,sca rho_M(h) P_CS(nu, g)] dd
//
// with T the transmittance (optical_depth.h), T_sun the transmittance from the point to the
// sun (0 in the Earth's shadow), P_R the Rayleigh and P_CS the Cornette-Shanks phase
// functions (phase_functions.h), E_sun the extraterrestrial solar irradiance. The outer
// integral uses the ray_quadrature.h pieces; the observer-side optical length at each node is
// the sum over the previous pieces plus a Gauss-Legendre integral over the node's own piece;
// the sun-side one is a full numerical integral per node. Everything in double precision,
// about 1e-10 relative error with the reference options.
// Pure function; thread-safe.
#pragma once

#include <limits>

#include "models/atmosphere/atmosphere_spectra.h"
#include "models/core/ray_quadrature.h"
#include "models/core/ray_scattering.h"

namespace clearsky {

// Single scattering and transmittance along the view ray, from the observer to the ground,
// the top of the atmosphere, or max_distance_m (aerial perspective), whichever comes first.
// An observer above the atmosphere sees the part of the ray inside it.
ScatteringAlongRay single_scattering_reference(
    const AtmosphereSpectra& atmosphere, const RaySunGeometry& ray,
    double max_distance_m = std::numeric_limits<double>::infinity(),
    const RayQuadratureOptions& options = RayQuadratureOptions::reference());

}  // namespace clearsky
