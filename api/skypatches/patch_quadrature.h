// The quadrature that averages a sky over each patch of a SkyPatchScheme
// (docs/building-energy.md "Patch values"): a band patch is a rectangle in (altitude, azimuth)
// with d Omega = cos(altitude) d altitude d azimuth, so a product Gauss-Legendre rule in those
// two coordinates integrates over exactly the patch, and a radiance smooth over the sphere
// stays smooth in them (in sin(altitude) it would not: sin(zenith) = sqrt(1 - u^2) is singular
// at the zenith and slows Gauss-Legendre near it). The cap uses polar coordinates about the
// zenith, d Omega = sin(theta) d theta d azimuth: Gauss-Legendre in theta and the midpoint
// rule in azimuth (exact for the low harmonics of a periodic integrand). The weights of a patch
// sum to its solid angle to rounding.
//
// Order: n x n nodes per band patch (the cap: n x 4n), n = nodes_per_side; the patches near the
// sun, where the circumsolar radiance varies fastest, get sun_refinement x n per side. The
// default order keeps about 1.5 degrees between nodes whatever the subdivision; its
// convergence is measured in tests/api/skypatches/patch_quadrature_test.cpp and stated in
// docs/building-energy.md.
// Pure functions; thread-safe.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "api/skypatches/sky_patch_scheme.h"
#include "models/core/geometry.h"

namespace clearsky::api {

struct PatchQuadrature {
  std::vector<ViewDirection> views;
  std::vector<double> weights_sr;
  // The nodes of sky patch i (Radiance's patch i + 1) are [first[i], first[i + 1]).
  std::vector<std::size_t> first;
};

struct PatchQuadratureOrder {
  int nodes_per_side = 2;
  int sun_refinement = 1;  // factor on nodes_per_side near the sun
  // A patch is near the sun when the sun lies within this angle of the patch's centre
  // (radians), or in the patch.
  double near_sun_rad = 0;
};

// ceil(8 / MF) nodes per side (at least 2), 4 x that near the sun, "near" being within two
// band heights.
PatchQuadratureOrder default_patch_quadrature_order(const SkyPatchScheme& scheme);

// The nodes of every sky patch; sun (when above the horizon) selects the refined patches.
PatchQuadrature patch_quadrature(const SkyPatchScheme& scheme, const PatchQuadratureOrder& order,
                                 const std::optional<SunPosition>& sun);

}  // namespace clearsky::api
