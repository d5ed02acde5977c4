// GET /v1/irradiance: direct sun, diffuse sky and global irradiance on a horizontal or tilted
// plane (tilt from horizontal, surface_azimuth of the plane's normal clockwise from North,
// degrees), integrated (W/m2 over the model's answered grid) with illuminance (lx), and
// spectral (W/(m2.nm)) when spectral=true. component=all|direct|diffuse|global.
//  - direct = E_normal(lambda) max(0, cos(incidence)), zero when the sun is below the horizon
//    (the ground hides it);
//  - diffuse = the model's sky irradiance on the plane (sky radiance over the plane's
//    hemisphere; ground-reflected light excluded);
//  - global = direct + diffuse.
// Each component carries model_range_irradiance_w_m2 (over integrated_range_nm; its old name
// irradiance_w_m2 stays as a deprecated alias) and broadband_irradiance_w_m2 (300..4000 nm,
// with the molecular absorbers precipitable_water_cm and ozone_atm_cm:
// api/irradiance/broadband_irradiance.h), null for a model that cannot go broadband, whose
// answer names why (broadband_unavailable).
#include <cmath>
#include <optional>

#include "api/colour/xyz_weights.h"
#include "api/handlers/handlers.h"
#include "api/handlers/sky_radiance_query.h"
#include "api/irradiance/broadband_irradiance.h"
#include "models/atmosphere/atmosphere_parameter_table.h"
#include "models/atmosphere/spctral2.h"
#include "models/core/numeric.h"

namespace clearsky::api {

namespace {

nlohmann::json component_json(const Spectrum& e, const SkyModel& model,
                              const std::vector<std::size_t>& indices, const XyzWeights& xyz,
                              bool spectral, std::optional<double> broadband_w_m2) {
  const WavelengthGrid& grid = model.wavelengths();
  double integrated = 0.0;
  for (std::size_t i : indices) integrated += grid.integration_weight_nm(i) * e[i];
  nlohmann::json out = {
      {"model_range_irradiance_w_m2", finite(integrated)},
      {"irradiance_w_m2", finite(integrated)},  // deprecated alias (docs/http-api.md)
      {"broadband_irradiance_w_m2",
       broadband_w_m2 ? nlohmann::json(finite(*broadband_w_m2)) : nlohmann::json(nullptr)},
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
  AtmosphereParameters absorbers_atmosphere = config.atmosphere;
  for (const char* name : {"precipitable_water_cm", "ozone_atm_cm"}) {
    const AtmosphereParameterInfo& info = *find_atmosphere_parameter(name);
    info.set(absorbers_atmosphere,
             p.number_or(name, info.default_value, info.min_value, info.max_value));
  }
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
  double direct_on_plane = 0.0;  // direct / direct normal
  if (want_direct) {
    const SpectralSample s = model.sun_irradiance(*state, viewpoint);
    require_answer(s.status,
                   s.status == SampleStatus::viewpoint_unsupported ? "altitude" : sun.parameter,
                   d.id);
    direct_normal = s.value;
    const double cos_incidence = dot(SkyDirection{plane.tilt_rad, plane.azimuth_rad}.unit_vector(),
                                     SkyDirection{sun.sun}.unit_vector());
    const double above_horizon = sun.sun.zenith_rad <= 0.5 * kPi ? 1.0 : 0.0;
    direct_on_plane = std::max(0.0, cos_incidence) * above_horizon;
    direct = direct_normal * direct_on_plane;
  }
  if (want_diffuse) {
    const SpectralSample s = model.sky_irradiance(*state, viewpoint, plane);
    require_answer(s.status,
                   s.status == SampleStatus::viewpoint_unsupported ? "altitude" : sun.parameter,
                   d.id);
    diffuse = s.value;
  }

  // The broadband figures (api/irradiance/broadband_irradiance.h).
  const std::optional<std::string> broadband_unavailable = broadband_unavailable_reason(d);
  const BroadbandConditions conditions{
      .sun_zenith_rad = sun.sun.zenith_rad,
      .altitude_m = viewpoint.altitude_m,
      .atmosphere = absorbers_atmosphere,
      .earth_sun_distance_factor = sun.unix_time_utc_s ? spctral2::earth_sun_distance_factor(
                                                             day_of_year_utc(*sun.unix_time_utc_s))
                                                       : 1.0};
  std::optional<double> bb_direct_normal, bb_direct, bb_diffuse;
  if (!broadband_unavailable) {
    if (want_direct) {
      bb_direct_normal =
          broadband_direct_normal_w_m2({model.wavelengths(), m.indices, direct_normal}, conditions);
      bb_direct = *bb_direct_normal * direct_on_plane;
    }
    if (want_diffuse)
      bb_diffuse = broadband_diffuse_w_m2({model.wavelengths(), m.indices, diffuse}, conditions);
  }
  std::optional<double> bb_global;
  if (bb_direct && bb_diffuse) bb_global = *bb_direct + *bb_diffuse;

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
  if (broadband_unavailable) {
    body["broadband"] = nullptr;
    body["broadband_unavailable"] = *broadband_unavailable;
  } else {
    body["broadband"] = {
        {"range_nm", {kBroadbandMinNm, kBroadbandMaxNm}},
        {"precipitable_water_cm", absorbers_atmosphere.precipitable_water_cm},
        {"ozone_atm_cm", absorbers_atmosphere.ozone_atm_cm},
        {"earth_sun_distance_factor", conditions.earth_sun_distance_factor},
        {"method",
         "the model's spectra inside integrated_range_nm, absorbed by water vapour, "
         "ozone and mixed gases (Bird and Riordan 1986); outside it the model's "
         "extinction and SPCTRAL2's diffuse scaled to the model at the range ends"}};
  }
  if (spectral) body["wavelengths_nm"] = m.wavelengths_nm;
  const bool all = component == "all";
  if (all || component == "direct") {
    body["direct_normal"] =
        component_json(direct_normal, model, m.indices, xyz, spectral, bb_direct_normal);
    body["direct"] = component_json(direct, model, m.indices, xyz, spectral, bb_direct);
  }
  if (all || component == "diffuse")
    body["diffuse"] = component_json(diffuse, model, m.indices, xyz, spectral, bb_diffuse);
  if (all || component == "global")
    body["global"] = component_json(direct + diffuse, model, m.indices, xyz, spectral, bb_global);
  add_quality_members(body, quality, m.served_quality);
  ApiResponse response = json_response(body);
  response.model_id = d.id;
  add_quality_headers(response.headers, quality, m.served_quality);
  return response;
}

}  // namespace clearsky::api
