// GET /v1/irradiance: direct sun, diffuse sky and global irradiance on a horizontal or tilted
// plane (tilt from horizontal, surface_azimuth of the plane's normal clockwise from North,
// degrees), integrated (W/m2 over the model's answered grid) with illuminance (lx), and
// spectral (W/(m2.nm)) when spectral=true. component=all|direct|diffuse|global.
//  - direct = E_normal(lambda) max(0, cos(incidence)), zero when the sun is below the horizon
//    (the ground hides it);
//  - diffuse = the model's sky irradiance on the plane (sky radiance over the plane's
//    hemisphere; ground-reflected light excluded);
//  - global = direct + diffuse.
#include <cmath>

#include "api/colour/xyz_weights.h"
#include "api/handlers/handlers.h"
#include "api/handlers/sky_radiance_query.h"
#include "models/core/numeric.h"

namespace clearsky::api {

namespace {

nlohmann::json component_json(const Spectrum& e, const SkyModel& model,
                              const std::vector<std::size_t>& indices, const XyzWeights& xyz,
                              bool spectral) {
  const WavelengthGrid& grid = model.wavelengths();
  double integrated = 0.0;
  for (std::size_t i : indices) integrated += grid.integration_weight_nm(i) * e[i];
  nlohmann::json out = {{"irradiance_w_m2", finite(integrated)},
                        {"illuminance_lx", finite(xyz.luminance({e.data(), e.size()}))}};
  if (spectral) {
    nlohmann::json values = nlohmann::json::array();
    for (std::size_t i : indices) values.push_back(finite(e[i]));
    out["spectral_w_m2_nm"] = std::move(values);
  }
  return out;
}

}  // namespace

ApiResponse irradiance(const ApiContext& context, const ApiRequest& request) {
  if (request.method != "GET")
    throw ApiError(405, "method_not_allowed", "", "use GET for /v1/irradiance");
  Parameters p = request_parameters(request);
  const ModelFactory& factory = parse_model(p, context.models);
  const ModelDescriptor& d = *factory.descriptor;
  const SunSpec sun = parse_sun(p);
  const Viewpoint viewpoint = parse_viewpoint(p);
  ModelConfig config = parse_config(p, d);
  const RequestQuality quality = parse_quality(p, d, config, context.default_quality);
  const double tilt_deg = p.number_or("tilt", 0.0, 0.0, 180.0);
  const double surface_azimuth_deg = p.number_or("surface_azimuth", 180.0, -360.0, 360.0);
  const std::string component =
      p.choice("component", {"all", "direct", "diffuse", "global"}, "all");
  const bool spectral = p.boolean_or("spectral", false);
  p.reject_unused();

  const bool want_direct = component != "diffuse";
  const bool want_diffuse = component != "direct";
  if (want_direct && !d.capabilities.sun_irradiance) {
    throw cannot_answer("component", d.id, "it does not compute the direct sun irradiance");
  }
  if (want_diffuse && !d.capabilities.sky_irradiance) {
    throw cannot_answer("component", d.id, "it does not compute the sky irradiance");
  }
  const ModelOnGrid m = model_on_wavelengths(context.models, factory, std::move(config),
                                             std::nullopt, request.requester(), &quality);
  const SkyModel& model = *m.model;
  const auto state = prepare_sun(context.models, m.model, sun);
  const PlaneOrientation plane{degrees_to_radians(tilt_deg),
                               degrees_to_radians(surface_azimuth_deg)};
  const std::size_t n = model.wavelengths().size();

  Spectrum direct_normal(n, 0.0), direct(n, 0.0), diffuse(n, 0.0);
  if (want_direct) {
    const SpectralSample s = model.sun_irradiance(*state, viewpoint);
    require_answer(s.status,
                   s.status == SampleStatus::viewpoint_unsupported ? "altitude" : sun.parameter,
                   d.id);
    direct_normal = s.value;
    const double cos_incidence = dot(SkyDirection{plane.tilt_rad, plane.azimuth_rad}.unit_vector(),
                                     SkyDirection{sun.sun}.unit_vector());
    const double above_horizon = sun.sun.zenith_rad <= 0.5 * kPi ? 1.0 : 0.0;
    direct = direct_normal * (std::max(0.0, cos_incidence) * above_horizon);
  }
  if (want_diffuse) {
    const SpectralSample s = model.sky_irradiance(*state, viewpoint, plane);
    require_answer(s.status,
                   s.status == SampleStatus::viewpoint_unsupported ? "altitude" : sun.parameter,
                   d.id);
    diffuse = s.value;
  }

  const XyzWeights xyz(model.wavelengths());
  nlohmann::json body = {
      {"model", d.id},
      {"model_version", d.version},
      {"sun", sun_json(sun)},
      {"altitude_m", viewpoint.altitude_m},
      {"plane", {{"tilt_deg", tilt_deg}, {"surface_azimuth_deg", surface_azimuth_deg}}},
      {"integrated_range_nm",
       {model.wavelengths().lower_edge_nm(m.indices.front()),
        model.wavelengths().upper_edge_nm(m.indices.back())}},
      {"ground_reflection", "excluded"}};
  if (spectral) body["wavelengths_nm"] = m.wavelengths_nm;
  const bool all = component == "all";
  if (all || component == "direct") {
    body["direct_normal"] = component_json(direct_normal, model, m.indices, xyz, spectral);
    body["direct"] = component_json(direct, model, m.indices, xyz, spectral);
  }
  if (all || component == "diffuse")
    body["diffuse"] = component_json(diffuse, model, m.indices, xyz, spectral);
  if (all || component == "global")
    body["global"] = component_json(direct + diffuse, model, m.indices, xyz, spectral);
  add_quality_members(body, quality, m.served_quality);
  ApiResponse response = json_response(body);
  response.model_id = d.id;
  add_quality_headers(response.headers, quality, m.served_quality);
  return response;
}

}  // namespace clearsky::api
