// GET/POST /v1/radiance: spectral sky radiance, W/(m2.sr.nm), for one view or a batch.
// format=json (default): {"model", "sun", "altitude_m", "unit", "wavelengths_nm",
// "samples": [{"view_zenith_deg", "view_azimuth_deg", "radiance": [...]}]};
// format=csv: one row per view and wavelength
// (view_zenith_deg,view_azimuth_deg,wavelength_nm,radiance_w_m2_sr_nm).

#include "api/encode/csv_number.h"
#include "api/encode/radiance_json.h"
#include "api/fits/stored_fit_values.h"
#include "api/handlers/handlers.h"
#include "api/handlers/sky_radiance_query.h"
#include "api/http/answer_memory_reservation.h"

namespace clearsky::api {

ApiResponse radiance(const ApiContext& context, const ApiRequest& request) {
  Parameters p = request_parameters(request, {"views"});
  const ModelFactory& factory = parse_model(p, context.models);
  const SunSpec sun = parse_sun(p);
  const Viewpoint viewpoint = parse_viewpoint(p);
  SkyConfig sky = parse_sky_config(p, *factory.descriptor, stored_fit_lookup(context));
  ModelConfig& config = sky.config;
  const RequestQuality quality =
      parse_quality(p, *factory.descriptor, config, context.default_quality);
  const auto wavelengths = parse_wavelengths(p, context.limits);
  const std::string format = p.choice("format", {"json", "csv"}, "json");
  const ViewList views =
      request.method == "POST"
          ? parse_view_batch(request_body(request).value("views", nlohmann::json()), context.limits)
          : parse_single_view(p);
  p.reject_unused();

  const ModelOnGrid m = model_on_wavelengths(context.models, factory, std::move(config),
                                             wavelengths, request.requester(), &quality);
  // The answer is built whole: its bytes are reserved before the sky is computed and held
  // until it was sent (api/http/batch_answer_bytes.h).
  auto reservation = reserve_batch_answer_memory(context, views.views.size(),
                                                 m.model->wavelengths().size(), m.indices.size());
  const SpectralBatch batch = checked_sky_radiance(context.models, m.model, sun, viewpoint, views);

  ApiResponse response;
  response.model_id = factory.descriptor->id;
  add_quality_headers(response.headers, quality, m.served_quality);
  add_fit_headers(response.headers, sky.fit);
  response.held_until_sent = std::move(reservation);
  if (format == "csv") {
    std::string body = "view_zenith_deg,view_azimuth_deg,wavelength_nm,radiance_w_m2_sr_nm\n";
    for (std::size_t v = 0; v < batch.size(); ++v) {
      const auto spectrum = batch.spectrum(v);
      for (std::size_t k = 0; k < m.indices.size(); ++k) {
        body += csv_number(views.zenith_deg[v]) + ',' + csv_number(views.azimuth_deg[v]) + ',' +
                csv_number(m.wavelengths_nm[k]) + ',' + csv_number(spectrum[m.indices[k]]) + '\n';
      }
    }
    response.content_type = "text/csv";
    response.body = std::move(body);
    return response;
  }
  response.body =
      radiance_json({*factory.descriptor, sun, viewpoint, m.model->wavelengths(), m.wavelengths_nm,
                     m.indices, views, batch, quality, m.served_quality, sky.fit});
  return response;
}

}  // namespace clearsky::api
