// Irradiance of one sun on horizontal and tilted planes (plane_irradiance.h).
#include "api/irradiance/plane_irradiance.h"

#include <algorithm>
#include <cmath>

#include "api/request/sky_request.h"
#include "models/core/numeric.h"

namespace clearsky::api {

namespace {

void require(const SpectralSample& s, const std::string& parameter, const ModelDescriptor& d) {
  require_answer(s.status, s.status == SampleStatus::viewpoint_unsupported ? "altitude" : parameter,
                 d.id);
}

}  // namespace

Spectrum ground_albedo_spectrum(const SkyModel& model, const GroundReflection& ground) {
  if (ground.albedo) return Spectrum(model.wavelengths().size(), *ground.albedo);
  return model.atmosphere().ground_albedo;
}

HorizontalIrradiance horizontal_irradiance(const SkyModel& model, const SunState& sun,
                                           const Viewpoint& viewpoint, bool with_direct,
                                           bool with_sky, const std::string& parameter) {
  const std::size_t n = model.wavelengths().size();
  HorizontalIrradiance out;
  out.direct_normal = out.direct = out.diffuse = out.global = Spectrum(n, 0.0);
  out.with_direct = with_direct;
  out.with_sky = with_sky;
  out.beam_factor = std::max(0.0, std::cos(sun.sun().zenith_rad));
  const ModelDescriptor& d = model.descriptor();
  if (with_direct) {
    const SpectralSample s = model.sun_irradiance(sun, viewpoint);
    require(s, parameter, d);
    out.direct_normal = s.value;
    out.direct = s.value * out.beam_factor;
  }
  if (with_sky) {
    const SpectralSample s = model.sky_irradiance(sun, viewpoint, PlaneOrientation{});
    require(s, parameter, d);
    out.diffuse = s.value;
  }
  out.global = out.direct + out.diffuse;
  return out;
}

PlaneIrradiance plane_irradiance(const SkyModel& model, const SunState& sun,
                                 const Viewpoint& viewpoint, const PlaneOrientation& plane,
                                 const HorizontalIrradiance& horizontal, const Spectrum& albedo,
                                 const GroundReflection& ground, bool with_sky,
                                 const std::string& parameter,
                                 const PlaneSkyIrradianceTable* table) {
  const std::size_t n = model.wavelengths().size();
  PlaneIrradiance out;
  out.direct = out.sky_diffuse = out.ground_diffuse = out.global = Spectrum(n, 0.0);
  const SunPosition& s = sun.sun();
  const double cos_incidence = dot(SkyDirection{plane.tilt_rad, plane.azimuth_rad}.unit_vector(),
                                   SkyDirection{s}.unit_vector());
  const double above_horizon = s.zenith_rad <= 0.5 * kPi ? 1.0 : 0.0;
  out.with_sky = with_sky;
  out.with_ground = ground.included;
  out.beam_factor = std::max(0.0, cos_incidence) * above_horizon;
  out.direct = horizontal.direct_normal * out.beam_factor;
  if (with_sky) {
    std::optional<Spectrum> tabulated;
    if (table != nullptr && plane.tilt_rad != 0.0) tabulated = table->at(s);
    if (plane.tilt_rad == 0.0) {
      out.sky_diffuse = horizontal.diffuse;
    } else if (tabulated) {
      out.sky_diffuse = std::move(*tabulated);
    } else {
      const SpectralSample e = model.sky_irradiance(sun, viewpoint, plane);
      require(e, parameter, model.descriptor());
      out.sky_diffuse = e.value;
    }
  }
  if (ground.included) {
    const double view_factor = 0.5 * (1.0 - std::cos(plane.tilt_rad));
    out.ground_diffuse = horizontal.global * albedo * view_factor;
  }
  out.global = out.direct + out.sky_diffuse + out.ground_diffuse;
  return out;
}

double model_range_w_m2(const Spectrum& e, const WavelengthGrid& grid,
                        const std::vector<std::size_t>& indices) {
  double sum = 0.0;
  for (std::size_t i : indices) sum += grid.integration_weight_nm(i) * e[i];
  return sum;
}

IntegratedIrradiance integrated(const Spectrum& e, const SkyModel& model,
                                const std::vector<std::size_t>& indices, const XyzWeights& xyz) {
  IntegratedIrradiance out;
  out.irradiance_w_m2 = model_range_w_m2(e, model.wavelengths(), indices);
  out.illuminance_lx = xyz.luminance({e.data(), e.size()});
  return out;
}

}  // namespace clearsky::api
