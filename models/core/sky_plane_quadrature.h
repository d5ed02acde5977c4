// Quadrature rules for the sky irradiance of ground-view models: the integral of
// L(d) max(0, d . n) over the directions d above the horizon (d.z > 0), for a plane of normal n.
//
// Horizontal plane: Gauss-Legendre in cos(theta) times the midpoint rule in azimuth.
// Tilted plane: the sky it sees is a spherical lune, the intersection of the upper hemisphere
// and the plane's hemisphere, bounded by the two great circles through the axis
// a = z x n / |z x n|. With d = cos(alpha) a + sin(alpha) (cos(psi) z + sin(psi) (a x z)):
//   d.z = sin(alpha) cos(psi),  d . n = sin(alpha) cos(psi - tilt),
//   lune = {alpha in [0, pi], psi in [tilt - pi/2, pi/2]},  d Omega = sin(alpha) d alpha d psi,
// so the integrand sin^2(alpha) cos(psi - tilt) L(d) is smooth over a rectangle and
// Gauss-Legendre in both coordinates converges fast; a rule on the plane's hemisphere would
// instead cut through the sky at the horizon (a jump in the integrand: errors of 0.5..1.5% at
// 24 x 48 nodes for vertical and downward-facing planes).
// Pure functions; thread-safe.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "models/core/geometry.h"
#include "models/core/sky_model.h"

namespace clearsky {

struct WeightedDirections {
  std::vector<ViewDirection> views;
  std::vector<double> weights;  // sr, including the cosine factor d . n
};

// first_nodes x second_nodes directions: (cos theta, azimuth) for a horizontal plane (tilt
// below 1e-9 rad), (alpha, psi) for a tilted one; no direction for a plane facing straight down.
WeightedDirections sky_plane_quadrature(const PlaneOrientation& plane, int first_nodes,
                                        int second_nodes);

// The radiance of a batch of views above the horizon (out already sized), e.g. a model's
// SkyModel::radiance_to_integrate().
using SkyRadianceBatch = std::function<void(std::span<const ViewDirection>, SpectralBatch&)>;

// The sky irradiance (W/(m2.nm), n_wavelengths values) by that rule over `radiance`; samples
// whose status is not ok contribute nothing.
Spectrum sky_irradiance_on_plane(std::size_t n_wavelengths, const SkyRadianceBatch& radiance,
                                 const PlaneOrientation& plane, int first_nodes, int second_nodes);

}  // namespace clearsky
