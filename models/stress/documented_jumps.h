// The jumps a model documents, where a stress sweep must not count them as instabilities
// (docs/stability.md "Documented jumps"), each named:
//  - ground_horizon (view zenith): for models that answer views below the horizon, the view
//    that grazes the ground sphere, 90 degrees plus the dip acos(R / (R + h)) at altitude h.
//    Below it the view ends on the ground (its reflected light, or nothing), above it the view
//    crosses the whole atmosphere: the radiance is discontinuous there by construction.
//  - sunset (sun zenith): for models that answer suns below the horizon, the sun's centre at
//    the observer's geometric horizon, 90 degrees plus the same dip. The sun is a point: its
//    direct irradiance drops from its grazing value to 0 when the ground hides it.
//  - sun_zenith_bucket (sun zenith): for models with the option sun_zenith_bucket_deg > 0
//    (Haber: 1 degree by default; models/core/sun_state_cache.h), the edges between buckets,
//    (k + 1/2) times the width: every sun of a bucket is answered with the state of its centre,
//    so the answers are piecewise constant in the sun zenith and jump at the edges.
//  - ground_horizon and atmosphere_limb (altitude, per view below the horizon): the altitude at
//    which the view grazes the ground, R / sin(zenith) - R, and the top of the atmosphere,
//    R_top / sin(zenith) - R; above the second the view misses the atmosphere (radiance 0).
//  - study_viewer_sample_sphere (altitude, per view above the horizon): for models with the
//    option study_viewer_sample = 1 (Nishita93 on request, Nishita96 by default: the study's
//    trapezoid that starts with 0 at the observer), the altitudes of the Nishita93 spheres
//    (Nishita93Tables::sphere_radii_m). The view ray is sampled at its sphere crossings and the
//    segment from the observer to the first crossing weighs only the far end's integrand; when
//    the observer rises through a sphere that segment changes from nearly nothing to the whole
//    way to the next sphere (hundreds of km for a near-horizontal view), so the radiance jumps
//    there by construction (97% at view zenith 89.5, 32.8 to 32.9 km, for Nishita96).
//    With study_viewer_sample = 0 the radiance is continuous.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "models/core/sky_model.h"
#include "models/stress/neighbour_jumps.h"

namespace clearsky::stress {

// The documented jumps along a sweep of `coordinate` ("view_zenith_deg", "sun_zenith_deg",
// "altitude_m", ...) for an observer at altitude_m.
std::vector<DocumentedJump> documented_jumps(const SkyModel& model, std::string_view coordinate,
                                             double altitude_m);
// The documented jumps along an altitude sweep of the view at view_zenith_deg, for its chain.
std::vector<DocumentedJump> documented_altitude_jumps(const SkyModel& model, double view_zenith_deg,
                                                      const std::string& chain);

}  // namespace clearsky::stress
