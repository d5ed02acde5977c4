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
// | format             | -    | json     | json, csv, radiance        | csv: one row per patch (the sun last, if separate); radiance: with start only |
// | start, end, step, tz | -  | none     | api/request/time_steps.h   | a sky matrix: one vector per step (lat, lon instead of a sun) |
// clang-format on
//
// and the sky endpoints' model, sun (sun_zenith/sun_azimuth or lat, lon, time, ...), altitude
// and model parameters. With start (and end, step, tz: the instants of GET
// /v1/irradiance/series, api/request/time_steps.h) the answer is a sky matrix instead
// (api/skypatches/sky_patch_matrix.h, sky_patch_matrix_writer.h): one column per step, at most
// kMaxSkyMatrixValues values (steps x patches x components: 413 naming step), its floats held
// in the answer memory budget while it is sent. Fitted models (clamp_negative_fit) default to
// clamping here: a patch average is an integral, and like the sky irradiance it takes the
// physical limit of no light where the fit goes negative (models/core/fit_domain.h).
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>

#include "api/colour/xyz_weights.h"
#include "api/encode/csv_number.h"
#include "api/encode/iso8601_time.h"
#include "api/fits/stored_fit_values.h"
#include "api/handlers/handlers.h"
#include "api/handlers/sky_radiance_query.h"
#include "api/http/answer_memory_reservation.h"
#include "api/request/time_steps.h"
#include "api/skypatches/patch_value_encoder.h"
#include "api/skypatches/sky_patch_matrix_writer.h"
#include "api/skypatches/sky_patch_vector.h"
#include "models/core/fit_domain.h"

namespace clearsky::api {

namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

// The CSV column suffixes of one value's components (sky_patch_matrix_writer.h).
std::vector<std::string> component_suffixes(const std::string& output,
                                            const std::vector<double>& wavelengths_nm) {
  if (output == "luminance") return {""};
  if (output == "rgb") return {"_R", "_G", "_B"};
  std::vector<std::string> out;
  for (double wl : wavelengths_nm) {
    std::string suffix = csv_number(wl);  // appended, not "_" + ...: GCC 12's false
    suffix.insert(suffix.begin(), '_');   // -Wstringop-overflow on operator+(const char*, ...)
    out.push_back(suffix + "nm");
  }
  return out;
}

// The sky matrix of a request with start: checked, computed, then written as it is sent.
ApiResponse sky_matrix_response(const ApiContext& context, const ModelOnGrid& m,
                                const RequestQuality& quality, std::shared_ptr<TimeSteps> times,
                                const Viewpoint& viewpoint, int mf, const std::string& scheme_name,
                                const std::string& sun_handling, const std::string& output,
                                double ground_reflectance, const std::string& format,
                                const std::optional<AppliedFit>& fit) {
  const SkyModel& model = *m.model;
  const ModelDescriptor& d = model.descriptor();
  auto scheme = std::make_shared<const SkyPatchScheme>(mf);
  const std::size_t components =
      output == "spectral" ? m.indices.size() : (output == "rgb" ? 3 : 1);
  const std::size_t values = times->steps * scheme->patch_count() * components;
  if (values > kMaxSkyMatrixValues) {
    throw too_large("step", std::to_string(times->steps) + " steps x " +
                                std::to_string(scheme->patch_count()) + " patches x " +
                                std::to_string(components) + " components is " +
                                std::to_string(values) + " values, above the limit of " +
                                std::to_string(kMaxSkyMatrixValues) +
                                "; ask for a longer step, a shorter period, fewer patches or "
                                "fewer components (output=rgb or luminance)");
  }
  require_answerable_suns(*times, model);
  auto reservation =
      reserve_answer_memory(context, values * sizeof(float), "the sky matrix",
                            "ask for a longer step, a shorter period or fewer patches");
  const XyzWeights xyz(model.wavelengths());
  PatchValueEncoder encoder{output, m.indices, xyz};
  auto matrix = std::make_shared<const SkyPatchMatrix>(
      compute_sky_patch_matrix(model, *times, viewpoint, *scheme,
                               sun_handling == "patch" ? SunHandling::patch : SunHandling::separate,
                               ground_reflectance, encoder));

  ApiResponse response;
  response.model_id = d.id;
  add_quality_headers(response.headers, quality, m.served_quality);
  add_fit_headers(response.headers, fit);
  response.held_until_sent = reservation;
  auto suffixes = component_suffixes(output, m.wavelengths_nm);
  if (format == "csv" || format == "radiance") {
    response.content_type = format == "csv" ? "text/csv" : "text/plain";
    response.stream = [matrix, times, scheme, suffixes, format, reservation](const ByteSink& sink) {
      const SkyMatrixAnswer answer{*matrix, *times, *scheme, suffixes};
      return format == "csv" ? write_sky_matrix_csv(answer, sink)
                             : write_sky_matrix_radiance(answer, sink);
    };
    return response;
  }
  const WavelengthGrid& grid = model.wavelengths();
  nlohmann::json head = {
      {"model", d.id},
      {"model_version", d.version},
      {"lat", times->position.latitude_deg},
      {"lon", times->position.longitude_deg},
      {"altitude_m", viewpoint.altitude_m},
      {"start", format_iso8601_time(times->start_unix_s, 0, true)},
      {"step", times->step_text},
      {"step_s", times->step_s},
      {"steps", times->steps},
      {"tz", times->tz ? nlohmann::json(*times->tz) : nlohmann::json(nullptr)},
      {"scheme", scheme_name},
      {"mf", mf},
      {"patch_count", scheme->patch_count()},
      {"sun_handling", sun_handling},
      {"output", output},
      {"unit", encoder.unit()},
      {"ground_reflectance", ground_reflectance},
      {"integrated_range_nm",
       {grid.lower_edge_nm(m.indices.front()), grid.upper_edge_nm(m.indices.back())}}};
  if (output == "spectral") head["wavelengths_nm"] = m.wavelengths_nm;
  if (output == "rgb") {
    head["gamut_clipped_values"] = encoder.clipped();
    head["gamut_mapping"] = "negative components clipped to 0";
  }
  add_quality_members(head, quality, m.served_quality);
  add_fit_member(head, fit);
  response.content_type = "application/json";
  response.stream = [matrix, times, scheme, suffixes, head, reservation](const ByteSink& sink) {
    return write_sky_matrix_json({*matrix, *times, *scheme, suffixes}, head, sink);
  };
  return response;
}

}  // namespace

ApiResponse skypatches(const ApiContext& context, const ApiRequest& request) {
  if (request.method != "GET")
    throw ApiError(405, "method_not_allowed", "", "use GET for /v1/skypatches");
  Parameters p = request_parameters(request);
  const ModelFactory& factory = parse_model(p, context.models);
  const ModelDescriptor& d = *factory.descriptor;
  // With start, a sky matrix: the instants and suns of the irradiance series.
  std::shared_ptr<TimeSteps> times;
  std::optional<SunSpec> single_sun;
  Viewpoint viewpoint;
  if (p.has("start")) {
    times = std::make_shared<TimeSteps>(parse_time_steps(p));
    viewpoint = Viewpoint{times->position.elevation_m};
  } else {
    single_sun = parse_sun(p);
    viewpoint = parse_viewpoint(p);
  }
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
  const std::string format = p.choice("format", {"json", "csv", "radiance"}, "json");
  p.reject_unused();
  if (format == "radiance" && !times)
    throw invalid_parameter("format", "radiance is the format of a sky matrix (with start)");
  if (times) require_per_sun_day_steps(*times, d);
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
  if (times) {
    return sky_matrix_response(context, m, quality, times, viewpoint, mf, scheme_name, sun_handling,
                               output, ground_reflectance, format, sky.fit);
  }
  const SunSpec& sun = *single_sun;
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
  PatchValueEncoder encode{output, m.indices, xyz};
  const auto geometry = [&](std::size_t k) -> std::array<double, 3> {
    const PatchGeometry g = patch_geometry(scheme, k);
    return {g.altitude_deg, g.azimuth_deg, g.solid_angle_sr};
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
      {"unit", encode.unit()},
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
    body["gamut_clipped_values"] = encode.clipped();
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
