// GET /v1/irradiance: direct sun, diffuse sky, ground-reflected and global irradiance on a
// horizontal or tilted plane (tilt from horizontal, surface_azimuth of the plane's normal
// clockwise from North, degrees), integrated (W/m2 over the model's answered grid) with
// illuminance (lx), and spectral (W/(m2.nm)) when spectral=true.
// component=all|direct|diffuse|ground_diffuse|global; the computation is
// api/irradiance/plane_irradiance.h (shared with GET /v1/irradiance/series):
//  - direct = E_normal(lambda) max(0, cos(incidence)), zero when the sun is below the horizon;
//  - diffuse = the model's sky irradiance on the plane (sky radiance over the plane's
//    hemisphere);
//  - ground_diffuse = albedo x global horizontal x (1 - cos tilt) / 2, the isotropic ground
//    (ground_albedo, or the model's ground albedo); ground_reflection=exclude leaves it out;
//  - global = direct + diffuse + ground_diffuse.
// Each component carries model_range_irradiance_w_m2 (over integrated_range_nm; its old name
// irradiance_w_m2 stays as a deprecated alias) and broadband_irradiance_w_m2 (300..4000 nm,
// with the molecular absorbers precipitable_water_cm and ozone_atm_cm:
// api/irradiance/broadband_irradiance.h), null for a model that cannot go broadband, whose
// answer names why (broadband_unavailable); the broadband step is
// api/irradiance/broadband_plane_irradiance.h, shared with the series.
#include <cmath>
#include <optional>

#include "api/fits/stored_fit_values.h"
#include "api/handlers/handlers.h"
#include "api/handlers/sky_radiance_query.h"
#include "api/irradiance/broadband_plane_irradiance.h"
#include "api/irradiance/broadband_request.h"
#include "api/irradiance/ground_reflection_request.h"
#include "api/irradiance/plane_irradiance.h"
#include "models/atmosphere/spctral2.h"
#include "models/core/numeric.h"

namespace clearsky::api {

namespace {

nlohmann::json component_json(const Spectrum& e, const SkyModel& model,
                              const std::vector<std::size_t>& indices, const XyzWeights& xyz,
                              bool spectral, std::optional<double> broadband_w_m2) {
  const IntegratedIrradiance sum = integrated(e, model, indices, xyz);
  nlohmann::json out = {
      {"model_range_irradiance_w_m2", finite(sum.irradiance_w_m2)},
      {"irradiance_w_m2", finite(sum.irradiance_w_m2)},  // deprecated alias (docs/http-api.md)
      {"broadband_irradiance_w_m2",
       broadband_w_m2 ? nlohmann::json(finite(*broadband_w_m2)) : nlohmann::json(nullptr)},
      {"illuminance_lx", finite(sum.illuminance_lx)}};
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
  SkyConfig sky = parse_sky_config(p, d, stored_fit_lookup(context));
  ModelConfig& config = sky.config;
  const RequestQuality quality = parse_quality(p, d, config, context.default_quality);
  const double tilt_deg = p.number_or("tilt", 0.0, 0.0, 180.0);
  const double surface_azimuth_deg = p.number_or("surface_azimuth", 180.0, -360.0, 360.0);
  const std::string component =
      p.choice("component", {"all", "direct", "diffuse", "ground_diffuse", "global"}, "all");
  const bool spectral = p.boolean_or("spectral", false);
  const AtmosphereParameters absorbers_atmosphere = parse_broadband_absorbers(p, config.atmosphere);
  const GroundReflection ground = parse_ground_reflection(p);
  p.reject_unused();
  if (component == "ground_diffuse" && !ground.included)
    throw conflicting_parameters("component", "ground_reflection=exclude");

  const bool all = component == "all";
  const bool want_ground =
      ground.included && (all || component == "global" || component == "ground_diffuse");
  // The ground is lit by the global horizontal irradiance: it needs both of the model's parts.
  const bool want_direct = component != "diffuse" || want_ground;
  const bool want_diffuse = component != "direct" || want_ground;
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
  const HorizontalIrradiance horizontal =
      horizontal_irradiance(model, *state, viewpoint, want_direct, want_diffuse, sun.parameter);
  const GroundReflection used{want_ground, ground.albedo};
  const PlaneIrradiance on_plane =
      plane_irradiance(model, *state, viewpoint, plane, horizontal,
                       ground_albedo_spectrum(model, ground), used, want_diffuse, sun.parameter);

  // The broadband figures (api/irradiance/broadband_plane_irradiance.h).
  const std::optional<std::string> broadband_unavailable = broadband_unavailable_reason(d);
  const BroadbandConditions conditions{
      .sun_zenith_rad = sun.sun.zenith_rad,
      .altitude_m = viewpoint.altitude_m,
      .atmosphere = absorbers_atmosphere,
      .earth_sun_distance_factor = sun.unix_time_utc_s ? spctral2::earth_sun_distance_factor(
                                                             day_of_year_utc(*sun.unix_time_utc_s))
                                                       : 1.0};
  const XyzWeights xyz(model.wavelengths());
  BroadbandHorizontalIrradiance bb_horizontal;
  BroadbandPlaneIrradiance bb_plane;
  if (!broadband_unavailable) {
    const BroadbandExtension extension(model.wavelengths(), m.indices, conditions);
    bb_horizontal = broadband_horizontal_irradiance(extension, horizontal);
    bb_plane = broadband_plane_irradiance(extension, horizontal, bb_horizontal, on_plane);
  }

  nlohmann::json body = {
      {"model", d.id},
      {"model_version", d.version},
      {"sun", sun_json(sun)},
      {"altitude_m", viewpoint.altitude_m},
      {"plane", {{"tilt_deg", tilt_deg}, {"surface_azimuth_deg", surface_azimuth_deg}}},
      {"integrated_range_nm",
       {model.wavelengths().lower_edge_nm(m.indices.front()),
        model.wavelengths().upper_edge_nm(m.indices.back())}},
      {"ground_reflection", ground_reflection_json(ground)}};
  body["broadband"] = broadband_json(broadband_unavailable, absorbers_atmosphere);
  if (broadband_unavailable) {
    body["broadband_unavailable"] = *broadband_unavailable;
  } else {
    body["broadband"]["earth_sun_distance_factor"] = conditions.earth_sun_distance_factor;
  }
  if (spectral) body["wavelengths_nm"] = m.wavelengths_nm;
  if (all || component == "direct") {
    body["direct_normal"] = component_json(horizontal.direct_normal, model, m.indices, xyz,
                                           spectral, bb_horizontal.direct_normal_w_m2);
    body["direct"] =
        component_json(on_plane.direct, model, m.indices, xyz, spectral, bb_plane.direct_w_m2);
  }
  if (all || component == "diffuse")
    body["diffuse"] = component_json(on_plane.sky_diffuse, model, m.indices, xyz, spectral,
                                     bb_plane.sky_diffuse_w_m2);
  if (want_ground)
    body["ground_diffuse"] = component_json(on_plane.ground_diffuse, model, m.indices, xyz,
                                            spectral, bb_plane.ground_diffuse_w_m2);
  if (all || component == "global")
    body["global"] =
        component_json(on_plane.global, model, m.indices, xyz, spectral, bb_plane.global_w_m2);
  add_quality_members(body, quality, m.served_quality);
  add_fit_member(body, sky.fit);
  ApiResponse response = json_response(body);
  response.model_id = d.id;
  add_quality_headers(response.headers, quality, m.served_quality);
  add_fit_headers(response.headers, sky.fit);
  return response;
}

}  // namespace clearsky::api
