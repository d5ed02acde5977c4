// GET/POST /v1/rgb: linear sRGB (IEC 61966-2-1 primaries, D65 white, no transfer curve) and
// luminance (cd/m2) per view. method=spectral (default): the model on the paper's 40-bin grid,
// integrated against the CIE 1931 matching functions (models/colour); at quality=draft on the
// short colour grid of api/colour/colour_wavelengths.h instead, whose answer states the
// wavelengths and the measured colour error (docs/quality-levels.md). method=three: the
// paper's 3-wavelength method (section "Spectrum sampling"): the model built on the points
// 440, 550, 680 nm and c = k_c L(lambda_c) (models/colour/three_wavelength_rgb.h).
// RGB values are radiometric (XYZ with Y in W/(m2.sr)); luminance is 683 Y. Negative
// components (colours outside the sRGB gamut) are clipped to 0 and flagged per sample
// (api/colour/srgb_gamut.h); the luminance is the colour's before clipping.
#include <algorithm>
#include <limits>
#include <string>

#include "api/colour/colour_wavelengths.h"
#include "api/colour/srgb_gamut.h"
#include "api/colour/xyz_weights.h"
#include "api/fits/stored_fit_values.h"
#include "api/handlers/handlers.h"
#include "api/handlers/sky_radiance_query.h"
#include "api/http/answer_memory_reservation.h"
#include "models/colour/three_wavelength_rgb.h"

namespace clearsky::api {

namespace {

// The numbers an answer gives per view: rgb (3), gamut_clipped, luminance_cd_m2.
constexpr std::size_t kRgbSampleNumbers = 5;

const ThreeWavelengthRgb& three_wavelength_method() {
  static const ThreeWavelengthRgb method;
  return method;
}

}  // namespace

ApiResponse rgb(const ApiContext& context, const ApiRequest& request) {
  Parameters p = request_parameters(request, {"views"});
  const ModelFactory& factory = parse_model(p, context.models);
  const SunSpec sun = parse_sun(p);
  const Viewpoint viewpoint = parse_viewpoint(p);
  SkyConfig sky = parse_sky_config(p, *factory.descriptor, stored_fit_lookup(context));
  ModelConfig& config = sky.config;
  const RequestQuality quality =
      parse_quality(p, *factory.descriptor, config, context.default_quality);
  const std::string method = p.choice("method", {"spectral", "three"}, "spectral");
  const ViewList views =
      request.method == "POST"
          ? parse_view_batch(request_body(request).value("views", nlohmann::json()), context.limits)
          : parse_single_view(p);
  p.reject_unused();

  const ThreeWavelengthRgb& three = three_wavelength_method();
  std::optional<std::vector<double>> wavelengths;
  if (method == "three") {
    wavelengths = three.grid().nanometres();
    config.wavelengths = three.grid();
  }
  // The level's colour grid when it is not the model's own (docs/quality-levels.md "Colour
  // wavelengths").
  const std::optional<std::vector<double>> colour_nm =
      method == "spectral" ? colour_wavelengths_nm(quality.level) : std::nullopt;
  if (colour_nm) wavelengths = colour_nm;
  const ModelOnGrid m = model_on_wavelengths(context.models, factory, std::move(config),
                                             wavelengths, request.requester(), &quality);
  // The answer is built whole: its bytes are reserved before the sky is computed and held
  // until it was sent (api/http/batch_answer_bytes.h).
  auto reservation = reserve_batch_answer_memory(context, views.views.size(),
                                                 m.model->wavelengths().size(), kRgbSampleNumbers);
  const SpectralBatch batch = checked_sky_radiance(context.models, m.model, sun, viewpoint, views);

  nlohmann::json samples = nlohmann::json::array();
  std::size_t clipped_samples = 0;
  const XyzWeights xyz = colour_nm ? XyzWeights::interpolating(m.model->wavelengths())
                                   : XyzWeights(m.model->wavelengths());
  for (std::size_t v = 0; v < batch.size(); ++v) {
    const auto spectrum = batch.spectrum(v);
    LinearSrgb c;
    double luminance = 0;
    if (method == "three") {
      c = three.rgb(spectrum[m.indices[2]], spectrum[m.indices[1]], spectrum[m.indices[0]]);
      luminance = kMaxLuminousEfficacy * linear_srgb_to_xyz(c).y;
    } else {
      const Xyz x = xyz.xyz(spectrum);
      c = xyz_to_linear_srgb(x);
      luminance = kMaxLuminousEfficacy * x.y;
    }
    const GamutMappedSrgb mapped = clip_to_srgb_gamut(c);
    if (mapped.clipped) ++clipped_samples;
    samples.push_back({{"view_zenith_deg", views.zenith_deg[v]},
                       {"view_azimuth_deg", views.azimuth_deg[v]},
                       {"rgb", {finite(mapped.rgb.r), finite(mapped.rgb.g), finite(mapped.rgb.b)}},
                       {"gamut_clipped", mapped.clipped},
                       {"luminance_cd_m2", finite(luminance)}});
  }
  nlohmann::json body = {{"model", factory.descriptor->id},
                         {"model_version", factory.descriptor->version},
                         {"method", method},
                         {"sun", sun_json(sun)},
                         {"altitude_m", viewpoint.altitude_m},
                         {"colour_space", "linear sRGB (D65), radiometric: Y in W/(m2.sr)"},
                         {"gamut_mapping", "negative components clipped to 0"},
                         {"gamut_clipped_samples", clipped_samples},
                         {"samples", std::move(samples)}};
  if (colour_nm) {
    // The spectrum between the colour grid's wavelengths is interpolated and held beyond them
    // over the whole table of the matching functions (XyzWeights::interpolating).
    const auto& nm = m.model->wavelengths().nanometres();
    body["integrated_range_nm"] = {360.0, 830.0};
    body["colour_wavelengths_nm"] = nm;
    const std::optional<ColourError> error =
        quality.overridden.empty() ? draft_colour_error(factory.descriptor->id) : std::nullopt;
    body["colour_error"] = error ? nlohmann::json{{"against", "40 wavelengths"},
                                                  {"measure", "CIE Delta E 2000 over the skydome"},
                                                  {"median", error->median},
                                                  {"p95", error->p95},
                                                  {"max", error->max}}
                                 : nlohmann::json(nullptr);
  } else if (method == "spectral") {
    // A model with a narrower range than the grid (Hosek: 320..720 nm) contributes nothing
    // beyond it; say so instead of presenting a partial integral as the full CIE colour.
    const WavelengthGrid& grid = m.model->wavelengths();
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    bool partial = false;
    for (std::size_t w = 0; w < grid.size(); ++w) {
      if (!m.model->answers_wavelength(w)) {
        partial = true;
        continue;
      }
      lo = std::min(lo, grid.lower_edge_nm(w));
      hi = std::max(hi, grid.upper_edge_nm(w));
    }
    body["integrated_range_nm"] = {grid.lower_edge_nm(0), grid.upper_edge_nm(grid.size() - 1)};
    if (partial) {
      body["integrated_range_nm"] = {lo, hi};
      body["warning"] = "the model answers only part of the grid; the CIE integral covers [" +
                        std::to_string(lo) + ", " + std::to_string(hi) +
                        "] nm (missing light counts as zero)";
    }
  }
  add_quality_members(body, quality, m.served_quality);
  add_fit_member(body, sky.fit);
  ApiResponse response = json_response(body);
  response.model_id = factory.descriptor->id;
  add_quality_headers(response.headers, quality, m.served_quality);
  add_fit_headers(response.headers, sky.fit);
  response.held_until_sent = std::move(reservation);
  return response;
}

}  // namespace clearsky::api
