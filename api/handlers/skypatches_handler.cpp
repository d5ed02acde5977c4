// GET /v1/skypatches: a sky vector for Radiance's daylight-coefficient tools
// (docs/building-energy.md): the model's radiance averaged over each Tregenza or Reinhart patch
// in Radiance's numbering (api/skypatches/sky_patch_scheme.h, patch 0 the ground), with the sun
// as its own source or folded into its patch (api/skypatches/sky_patch_vector.h).
//
// clang-format off
// | parameter          | unit | default  | range                      | meaning                                        |
// |--------------------|------|----------|----------------------------|------------------------------------------------|
// | scheme             | -    | tregenza | tregenza, reinhart         | the subdivision (Tregenza: 145 patches + ground) |
// | mf                 | -    | 1        | [1, 6], integer            | Reinhart's subdivision (scheme=reinhart only)  |
// | sun                | -    | separate | separate, patch            | the sun as its own source, or in its patch     |
// | output             | -    | spectral | spectral, rgb, luminance   | W/(m2.sr.nm); Radiance RGB, W/(m2.sr); cd/m2   |
// | wavelengths        | nm   | model's  | as on /v1/radiance         | output=spectral only; patches x wavelengths <= 1e6 (413) |
// | ground_reflectance | -    | 0.2      | [0, 1]                     | patch 0: Lambertian ground (gendaymtx's -g)    |
// | format             | -    | json     | json, csv                  | csv: one row per patch (the sun last, if separate) |
// clang-format on
//
// and the sky endpoints' model, sun (sun_zenith/sun_azimuth or lat, lon, time, ...), altitude
// and model parameters. Fitted models (clamp_negative_fit) default to clamping here: a patch
// average is an integral, and like the sky irradiance it takes the physical limit of no light
// where the fit goes negative (models/core/fit_domain.h).
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "api/colour/radiance_rgb.h"
#include "api/colour/xyz_weights.h"
#include "api/fits/stored_fit_values.h"
#include "api/handlers/handlers.h"
#include "api/handlers/sky_radiance_query.h"
#include "api/skypatches/sky_patch_vector.h"
#include "models/core/fit_domain.h"

namespace clearsky::api {

namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

std::string csv_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(finite(x)));
  return buffer;
}

// One patch's (or the sun's) values in the requested output.
struct ValueEncoder {
  const std::string& output;
  const ModelOnGrid& m;
  const XyzWeights& xyz;
  std::size_t clipped = 0;

  std::vector<double> values(const Spectrum& spectrum) {
    if (output == "spectral") {
      std::vector<double> out;
      for (std::size_t i : m.indices) out.push_back(spectrum[i]);
      return out;
    }
    const Xyz colour = xyz.xyz({spectrum.data(), spectrum.size()});
    if (output == "luminance") return {kMaxLuminousEfficacy * colour.y};
    const ClippedRadianceRgb rgb = clip_radiance_rgb(xyz_to_radiance_rgb(colour));
    if (rgb.clipped) ++clipped;
    return {rgb.rgb.r, rgb.rgb.g, rgb.rgb.b};
  }
  nlohmann::json json(const Spectrum& spectrum) {
    const std::vector<double> v = values(spectrum);
    if (output == "luminance") return finite(v[0]);
    nlohmann::json out = nlohmann::json::array();
    for (double x : v) out.push_back(finite(x));
    return out;
  }
};

const char* unit_of(const std::string& output) {
  if (output == "spectral") return "W/(m2.sr.nm)";
  if (output == "rgb") return "W/(m2.sr)";
  return "cd/m2";
}

}  // namespace

ApiResponse skypatches(const ApiContext& context, const ApiRequest& request) {
  if (request.method != "GET")
    throw ApiError(405, "method_not_allowed", "", "use GET for /v1/skypatches");
  Parameters p = request_parameters(request);
  const ModelFactory& factory = parse_model(p, context.models);
  const ModelDescriptor& d = *factory.descriptor;
  const SunSpec sun = parse_sun(p);
  const Viewpoint viewpoint = parse_viewpoint(p);
  SkyConfig sky = parse_sky_config(p, d, stored_fit_lookup(context));
  ModelConfig& config = sky.config;
  const RequestQuality quality = parse_quality(p, d, config, context.default_quality);
  if (d.find_parameter(kClampNegativeFitOption) &&
      !config.options.contains(kClampNegativeFitOption))
    config.options[kClampNegativeFitOption] = 1.0;
  const std::string scheme_name = p.choice("scheme", {"tregenza", "reinhart"}, "tregenza");
  const int mf = scheme_name == "reinhart"
                     ? static_cast<int>(p.integer("mf", 1, kMaxSkyPatchSubdivision).value_or(1))
                     : 1;
  const std::string sun_handling = p.choice("sun", {"separate", "patch"}, "separate");
  const std::string output = p.choice("output", {"spectral", "rgb", "luminance"}, "spectral");
  const auto wavelengths =
      output == "spectral" ? parse_wavelengths(p, context.limits) : std::nullopt;
  const double ground_reflectance = p.number_or("ground_reflectance", 0.2, 0.0, 1.0);
  const std::string format = p.choice("format", {"json", "csv"}, "json");
  p.reject_unused();
  const SkyPatchScheme scheme(mf);
  // Bounded answers: at most kMaxPatchValues numbers (patches x wavelengths), e.g. MF 6 with 192
  // wavelengths or Tregenza with 2000. A spectral MF 6 vector on 1881 wavelengths was a 195 MB
  // JSON body and a 640 MB peak; 1e6 values are about 20 MB.
  constexpr std::size_t kMaxPatchValues = 1000000;
  if (wavelengths && scheme.patch_count() * wavelengths->size() > kMaxPatchValues) {
    throw too_large("wavelengths", "at most " + std::to_string(kMaxPatchValues) +
                                       " values (patches x wavelengths) per sky vector; " +
                                       std::to_string(scheme.patch_count()) + " patches x " +
                                       std::to_string(wavelengths->size()) + " wavelengths");
  }

  const ModelOnGrid m = model_on_wavelengths(context.models, factory, std::move(config),
                                             wavelengths, request.requester(), &quality);
  const SkyModel& model = *m.model;
  const auto state = prepare_sun(context.models, m.model, sun);
  const PatchQuadratureOrder order = default_patch_quadrature_order(scheme);
  const SkyPatchVector vector = compute_sky_patch_vector(
      model, *state, viewpoint, scheme, order,
      sun_handling == "patch" ? SunHandling::patch : SunHandling::separate, ground_reflectance);
  require_answer(vector.status,
                 vector.status == SampleStatus::viewpoint_unsupported ? "altitude" : sun.parameter,
                 d.id);

  const XyzWeights xyz(model.wavelengths());
  ValueEncoder encode{output, m, xyz};
  const auto patches = scheme.sky_patches();
  // Centre altitude and azimuth (degrees) and solid angle of patch k; the ground's centre is
  // the nadir.
  const auto geometry = [&](std::size_t k) -> std::array<double, 3> {
    if (k == 0) return {-90.0, 0.0, 2.0 * std::numbers::pi};
    const SkyPatch& patch = patches[k - 1];
    return {patch.centre_altitude_rad * kDegreesPerRadian,
            patch.centre_azimuth_rad * kDegreesPerRadian, patch.solid_angle_sr};
  };
  const double sun_altitude_deg = 90.0 - sun.zenith_deg;

  ApiResponse response;
  if (format == "csv") {
    std::string body = "patch,altitude_deg,azimuth_deg,solid_angle_sr";
    if (output == "spectral") {
      for (double wl : m.wavelengths_nm) body += ",L_" + csv_number(wl) + "nm";
    } else {
      body += output == "rgb" ? ",R,G,B" : ",luminance_cd_m2";
    }
    body += '\n';
    const auto row = [&](const std::string& name, const std::array<double, 3>& g,
                         const Spectrum& spectrum) {
      body += name + ',' + csv_number(g[0]) + ',' + csv_number(g[1]) + ',' + csv_number(g[2]);
      for (double x : encode.values(spectrum)) body += ',' + csv_number(x);
      body += '\n';
    };
    for (std::size_t k = 0; k < vector.patches.size(); ++k)
      row(std::to_string(k), geometry(k), vector.patches[k]);
    if (vector.sun) {
      row("sun", {sun_altitude_deg, sun.azimuth_deg, vector.sun->solid_angle_sr},
          vector.sun->radiance);
    }
    response.body = std::move(body);
    response.content_type = "text/csv";
    response.model_id = d.id;
    add_quality_headers(response.headers, quality, m.served_quality);
    add_fit_headers(response.headers, sky.fit);
    return response;
  }

  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t k = 0; k < vector.patches.size(); ++k) {
    const auto g = geometry(k);
    rows.push_back({{"patch", k},
                    {"altitude_deg", g[0]},
                    {"azimuth_deg", g[1]},
                    {"solid_angle_sr", g[2]},
                    {"value", encode.json(vector.patches[k])}});
  }
  nlohmann::json sun_source = nullptr;
  if (vector.sun) {
    const Vec3 v = vector.sun->direction.unit_vector();
    sun_source = {{"altitude_deg", sun_altitude_deg},
                  {"azimuth_deg", sun.azimuth_deg},
                  {"direction", {v.x, v.y, v.z}},
                  {"solid_angle_sr", vector.sun->solid_angle_sr},
                  {"value", encode.json(vector.sun->radiance)}};
  }
  const WavelengthGrid& grid = model.wavelengths();
  double diffuse_horizontal_w_m2 = 0.0;
  for (std::size_t i : m.indices)
    diffuse_horizontal_w_m2 += grid.integration_weight_nm(i) * vector.diffuse_horizontal[i];

  nlohmann::json body = {
      {"model", d.id},
      {"model_version", d.version},
      {"sun", sun_json(sun)},
      {"altitude_m", viewpoint.altitude_m},
      {"scheme", scheme_name},
      {"mf", mf},
      {"patch_count", scheme.patch_count()},
      {"sun_handling", sun_handling},
      {"sun_patch", vector.sun_patch},
      {"output", output},
      {"unit", unit_of(output)},
      {"ground_reflectance", ground_reflectance},
      {"integrated_range_nm",
       {grid.lower_edge_nm(m.indices.front()), grid.upper_edge_nm(m.indices.back())}},
      {"diffuse_horizontal_w_m2", finite(diffuse_horizontal_w_m2)},
      {"quadrature",
       {{"nodes_per_side", order.nodes_per_side},
        {"near_sun_nodes_per_side", order.nodes_per_side * order.sun_refinement},
        {"near_sun_deg", order.near_sun_rad * kDegreesPerRadian},
        {"directions", vector.directions}}},
      {"patches", std::move(rows)},
      {"sun_source", std::move(sun_source)}};
  if (output == "spectral") body["wavelengths_nm"] = m.wavelengths_nm;
  if (output == "rgb") {
    body["gamut_clipped_values"] = encode.clipped;
    body["gamut_mapping"] = "negative components clipped to 0";
  }
  add_quality_members(body, quality, m.served_quality);
  add_fit_member(body, sky.fit);
  response = json_response(body);
  response.model_id = d.id;
  add_quality_headers(response.headers, quality, m.served_quality);
  add_fit_headers(response.headers, sky.fit);
  return response;
}

}  // namespace clearsky::api
