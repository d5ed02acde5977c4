// The Lambertian ground of a skydome (GET /v1/skydome ground=albedo, docs/renderers.md): below
// the horizon every pixel sees the radiance of a horizontal Lambertian ground of the
// atmosphere's albedo rho(lambda) (AtmosphereSpectra::ground_albedo: grass, Feister and Grewe
// 1995, unless the request's albedo) lit by the model's sun and sky:
//   L_ground(lambda) = rho(lambda) / pi x (E_n(lambda) cos(theta_sun) + E_sky(lambda)),
// E_n the direct normal irradiance (0 with the sun below the horizon), E_sky the model's sky
// irradiance on the horizontal (ground-reflected light excluded). The same in every direction
// below the horizon: no aerial perspective between the viewpoint and the ground, no shadows.
#pragma once

#include <string>

#include "models/core/sky_model.h"

namespace clearsky::api {

// The ground radiance, W/(m2.sr.nm), on model.wavelengths(); a 422 naming ground when the model
// does not compute the sun's or the sky's irradiance for this sun and viewpoint.
Spectrum lambertian_ground_radiance(const SkyModel& model, const SunState& sun,
                                    const Viewpoint& viewpoint);

}  // namespace clearsky::api
