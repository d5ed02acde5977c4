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

// The sky irradiance (W/(m2.nm) on model.wavelengths()) of a ground-view model by that rule,
// through model.sky_radiance(); samples the model does not answer contribute nothing.
Spectrum sky_irradiance_on_plane(const SkyModel& model, const SunState& sun,
                                 const Viewpoint& viewpoint, const PlaneOrientation& plane,
                                 int first_nodes, int second_nodes);

// The radiance of a batch of views above the horizon, for a model that integrates something
// other than its public answers (e.g. a fit clamped at zero where it turns negative).
using SkyRadianceBatch = std::function<void(std::span<const ViewDirection>, SpectralBatch&)>;

// The same rule over `radiance` (n_wavelengths values per view); samples whose status is not
// ok contribute nothing.
Spectrum sky_irradiance_on_plane(std::size_t n_wavelengths, const SkyRadianceBatch& radiance,
                                 const PlaneOrientation& plane, int first_nodes, int second_nodes);

// The node counts ground-view models use: horizontal 24 x 48 directions (within 0.01% of a
// 200 x 400 rule), tilted 32 x 32 (within 0.4% of a fine rule up to a tilt of 150 degrees;
// measured on Preetham and Hosek, tests/models/*).
Spectrum ground_view_sky_irradiance(std::size_t n_wavelengths, const SkyRadianceBatch& radiance,
                                    const PlaneOrientation& plane);

}  // namespace clearsky
