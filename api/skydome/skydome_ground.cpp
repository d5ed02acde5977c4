// The Lambertian ground of a skydome (skydome_ground.h).
#include "api/skydome/skydome_ground.h"

#include <cmath>

#include "api/error/api_error.h"
#include "api/request/sky_request.h"
#include "models/core/numeric.h"

namespace clearsky::api {

Spectrum lambertian_ground_radiance(const SkyModel& model, const SunState& sun,
                                    const Viewpoint& viewpoint) {
  const ModelDescriptor& d = model.descriptor();
  if (!d.capabilities.sun_irradiance || !d.capabilities.sky_irradiance) {
    throw cannot_answer("ground", d.id,
                        "it does not compute the irradiance that lights the ground");
  }
  const std::size_t n = model.wavelengths().size();
  Spectrum irradiance(n, 0.0);
  const double cos_sun = std::cos(sun.sun().zenith_rad);
  if (cos_sun > 0.0) {
    const SpectralSample direct = model.sun_irradiance(sun, viewpoint);
    require_answer(direct.status, "ground", d.id);
    irradiance = direct.value * cos_sun;
  }
  const SpectralSample sky = model.sky_irradiance(sun, viewpoint);
  require_answer(sky.status, "ground", d.id);
  irradiance = irradiance + sky.value;
  const Spectrum& albedo = model.atmosphere().ground_albedo;
  Spectrum radiance(n, 0.0);
  for (std::size_t w = 0; w < n; ++w) radiance[w] = albedo[w] / kPi * irradiance[w];
  return radiance;
}

}  // namespace clearsky::api
