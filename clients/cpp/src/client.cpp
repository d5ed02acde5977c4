// clearsky::client::Client (client.h): each method builds its request target or body, sends it
// through HttpTransport and reads the answer into its typed result.
#include "clearsky/client/client.h"

#include <chrono>
#include <fstream>
#include <thread>
#include <utility>

#include "data_json.h"
#include "http_transport.h"
#include "json_fields.h"
#include "query_text.h"
#include "sky_json.h"

namespace clearsky::client {

namespace {

using detail::parse_answer;
using detail::QueryText;

nlohmann::json json_of(const HttpAnswer& answer) {
  return parse_answer(answer.body, answer.status);
}

template <typename Item, typename Read>
Page<Item> page_of(const HttpAnswer& answer, Read read) {
  const nlohmann::json items = json_of(answer);
  if (!items.is_array()) throw Error(answer.status, "invalid_answer", "a list is not an array");
  Page<Item> page;
  for (const nlohmann::json& item : items) page.items.push_back(read(item));
  page.next_cursor = next_cursor(answer.link);
  return page;
}

void add_page(QueryText& query, const PageRequest& page) {
  if (page.limit) query.add("limit", static_cast<std::int64_t>(*page.limit));
  query.add("cursor", page.cursor);
}

std::string id_path(const char* collection, std::int64_t id) {
  return std::string(collection) + "/" + std::to_string(id);
}

// Polls `read` until `done` holds or the wait's deadline passes.
template <typename State, typename Read, typename Done>
State poll(const WaitOptions& wait, const std::string& what, Read read, Done done) {
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::milliseconds(wait.timeout_ms);
  for (;;) {
    State state = read();
    if (done(state)) return state;
    if (std::chrono::steady_clock::now() >= deadline)
      throw Error(0, "timeout",
                  what + " did not finish within " + std::to_string(wait.timeout_ms) + " ms");
    std::this_thread::sleep_for(std::chrono::milliseconds(wait.poll_interval_ms));
  }
}

}  // namespace

Client::Client(ClientOptions options)
    : transport_(std::make_unique<HttpTransport>(std::move(options))) {}
Client::~Client() = default;
Client::Client(Client&&) noexcept = default;
Client& Client::operator=(Client&&) noexcept = default;

bool Client::healthy() const {
  try {
    return transport_->get("/healthz").status == 200;
  } catch (const Error&) {
    return false;
  }
}

std::string Client::readiness() const {
  return detail::member<std::string>(json_of(transport_->get("/readyz")), "status");
}

std::vector<ModelInfo> Client::models() const {
  return detail::models_of(json_of(transport_->get("/v1/models")));
}

SunPosition Client::sun(const SunRequest& request) const {
  QueryText query;
  const PlaceTime& place = request.place_time;
  query.add("lat", place.latitude);
  query.add("lon", place.longitude);
  query.add("time", place.time);
  query.add("altitude", request.altitude_m);
  query.add("pressure", place.pressure_mbar);
  query.add("temperature", place.temperature_c);
  query.add("delta_t", place.delta_t_s);
  query.add("refraction", place.refraction);
  return detail::sun_position_of(json_of(transport_->get(query.target("/v1/sun"))));
}

RadianceResult Client::radiance(const RadianceRequest& request) const {
  QueryText query;
  detail::add_sky_query(query, request);
  query.add("view_zenith", request.view.zenith_deg);
  query.add("view_azimuth", request.view.azimuth_deg);
  if (!request.wavelengths_nm.empty())
    query.add("wavelengths", detail::number_list_text(request.wavelengths_nm));
  return detail::radiance_of(json_of(transport_->get(query.target("/v1/radiance"))));
}

RadianceResult Client::radiance(const RadianceBatchRequest& request) const {
  return detail::radiance_of(
      json_of(transport_->post_json("/v1/radiance", detail::radiance_batch_json(request).dump())));
}

IrradianceResult Client::irradiance(const IrradianceRequest& request) const {
  QueryText query;
  detail::add_sky_query(query, request);
  query.add("tilt", request.tilt_deg);
  query.add("surface_azimuth", request.surface_azimuth_deg);
  query.add("component", request.component);
  if (request.spectral) query.add("spectral", true);
  query.add("precipitable_water_cm", request.precipitable_water_cm);
  query.add("ozone_atm_cm", request.ozone_atm_cm);
  query.add("ground_reflection", request.ground_reflection);
  query.add("ground_albedo", request.ground_albedo);
  return detail::irradiance_of(json_of(transport_->get(query.target("/v1/irradiance"))));
}

IrradianceSeriesResult Client::irradiance_series(const IrradianceSeriesRequest& request) const {
  QueryText query;
  query.add("model", request.model);
  query.add("lat", request.latitude);
  query.add("lon", request.longitude);
  query.add("start", request.start);
  query.add("end", request.end);
  query.add("tz", request.tz);
  query.add("step", request.step);
  if (!request.planes.empty()) {
    std::string planes;
    for (const auto& plane : request.planes) {
      if (!planes.empty()) planes += ',';
      planes += detail::number_list_text({plane.tilt_deg}) + ':' +
                detail::number_list_text({plane.surface_azimuth_deg});
    }
    query.add("planes", planes);
  }
  query.add("altitude", request.altitude_m);
  query.add("ground_reflection", request.ground_reflection);
  query.add("ground_albedo", request.ground_albedo);
  query.add("quality", request.quality);
  query.add("fit", request.fit);
  for (const auto& [name, value] : request.parameters)
    query.add(name, detail::parameter_text(value));
  return detail::irradiance_series_of(
      json_of(transport_->get(query.target("/v1/irradiance/series"))));
}

SkyPatchesResult Client::sky_patches(const SkyPatchesRequest& request) const {
  QueryText query;
  detail::add_sky_query(query, request);
  detail::add_sky_patch_options(query, request);
  return detail::sky_patches_of(json_of(transport_->get(query.target("/v1/skypatches"))));
}

SkyMatrixResult Client::sky_matrix(const SkyMatrixRequest& request) const {
  QueryText query;
  query.add("model", request.model);
  query.add("lat", request.latitude);
  query.add("lon", request.longitude);
  query.add("start", request.start);
  query.add("end", request.end);
  query.add("tz", request.tz);
  query.add("step", request.step);
  query.add("altitude", request.altitude_m);
  query.add("quality", request.quality);
  query.add("fit", request.fit);
  detail::add_sky_patch_options(query, request);
  for (const auto& [name, value] : request.parameters)
    query.add(name, detail::parameter_text(value));
  return detail::sky_matrix_of(json_of(transport_->get(query.target("/v1/skypatches"))));
}

RgbResult Client::rgb(const RgbRequest& request) const {
  QueryText query;
  detail::add_sky_query(query, request);
  query.add("view_zenith", request.view.zenith_deg);
  query.add("view_azimuth", request.view.azimuth_deg);
  query.add("method", request.method);
  return detail::rgb_of(json_of(transport_->get(query.target("/v1/rgb"))));
}

RgbResult Client::rgb(const RgbBatchRequest& request) const {
  return detail::rgb_of(
      json_of(transport_->post_json("/v1/rgb", detail::rgb_batch_json(request).dump())));
}

SkydomeDownload Client::skydome(const SkydomeRequest& request, std::ostream& out) const {
  QueryText query;
  detail::add_sky_query(query, request);
  query.add("projection", request.projection);
  if (request.size_px) query.add("size", static_cast<std::int64_t>(*request.size_px));
  query.add("channels", request.channels);
  query.add("pixel_type", request.pixel_type);
  query.add("method", request.method);
  if (!request.wavelengths_nm.empty())
    query.add("wavelengths", detail::number_list_text(request.wavelengths_nm));
  return transport_->get_to_stream(query.target("/v1/skydome"), out);
}

SkydomeDownload Client::skydome_to_file(const SkydomeRequest& request,
                                        const std::filesystem::path& file) const {
  std::filesystem::path part = file;
  part += ".part";
  SkydomeDownload download;
  try {
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    if (!out) throw Error(0, "write_failed", part.string() + ": cannot be created");
    download = skydome(request, out);
    out.close();
    if (!out) throw Error(0, "write_failed", part.string() + ": cannot be written");
    std::filesystem::rename(part, file);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(part, ignored);
    throw;
  }
  return download;
}

Page<DatasetSummary> Client::datasets(const PageRequest& page) const {
  QueryText query;
  add_page(query, page);
  return page_of<DatasetSummary>(transport_->get(query.target("/v1/datasets")),
                                 detail::dataset_summary_of);
}

Dataset Client::dataset(const std::string& name, const DatasetQuery& dataset_query) const {
  QueryText query;
  if (dataset_query.samples) query.add("samples", true);
  query.add("capture", dataset_query.capture);
  return detail::dataset_of(
      json_of(transport_->get(query.target("/v1/datasets/" + detail::path_segment(name)))));
}

ImportState Client::upload_dataset(const DatasetUpload& upload,
                                   const UploadProgress& progress) const {
  QueryText query;
  query.add("name", upload.name);
  query.add("format", upload.format);
  return detail::import_state_of(
      json_of(transport_->post_file(query.target("/v1/datasets"), upload.archive, progress)));
}

std::string Client::delete_dataset(const std::string& name) const {
  return detail::member<std::string>(
      json_of(transport_->remove("/v1/datasets/" + detail::path_segment(name))), "deleted");
}

Page<ImportState> Client::imports(const ImportFilter& filter) const {
  QueryText query;
  query.add("status", filter.status);
  query.add("dataset", filter.dataset);
  add_page(query, filter);
  return page_of<ImportState>(transport_->get(query.target("/v1/imports")),
                              detail::import_state_of);
}

ImportState Client::import_state(std::int64_t id) const {
  return detail::import_state_of(json_of(transport_->get(id_path("/v1/imports", id))));
}

ImportState Client::wait_for_import(std::int64_t id, const WaitOptions& wait) const {
  return poll<ImportState>(
      wait, "import " + std::to_string(id), [&] { return import_state(id); },
      [](const ImportState& state) { return state.finished(); });
}

EvaluationTicket Client::create_evaluation(const EvaluationRequest& request) const {
  return detail::ticket_of(json_of(
      transport_->post_json("/v1/evaluations", detail::evaluation_request_json(request).dump())));
}

EvaluationTicket Client::evaluation_ticket(std::int64_t ticket) const {
  return detail::ticket_of(json_of(transport_->get(id_path("/v1/evaluations/tickets", ticket))));
}

EvaluationTicket Client::wait_for_ticket(std::int64_t ticket, const WaitOptions& wait) const {
  return poll<EvaluationTicket>(
      wait, "evaluation ticket " + std::to_string(ticket),
      [&] { return evaluation_ticket(ticket); },
      [](const EvaluationTicket& state) { return state.done(); });
}

Evaluation Client::evaluation(std::int64_t id, const EvaluationQuery& evaluation_query) const {
  QueryText query;
  query.add("samples", evaluation_query.samples);
  query.add("capture", evaluation_query.capture);
  return detail::evaluation_of(
      json_of(transport_->get(query.target(id_path("/v1/evaluations", id)))));
}

Page<EvaluationSummary> Client::evaluations(const EvaluationFilter& filter) const {
  QueryText query;
  query.add("model", filter.model);
  query.add("dataset", filter.dataset);
  query.add("status", filter.status);
  query.add("since", filter.since);
  query.add("until", filter.until);
  query.add("job", filter.job);
  add_page(query, filter);
  return page_of<EvaluationSummary>(transport_->get(query.target("/v1/evaluations")),
                                    detail::evaluation_summary_of);
}

AerosolInversion Client::upload_aerosols(const std::string& name,
                                         const std::filesystem::path& file) const {
  QueryText query;
  query.add("name", name);
  return detail::aerosol_inversion_of(
      json_of(transport_->post_file(query.target("/v1/aerosols"), file, {})));
}

Page<AerosolInversion> Client::aerosol_inversions(const PageRequest& page) const {
  QueryText query;
  add_page(query, page);
  return page_of<AerosolInversion>(transport_->get(query.target("/v1/aerosols")),
                                   detail::aerosol_inversion_of);
}

AerosolInversion Client::aerosol_inversion(std::int64_t id) const {
  return detail::aerosol_inversion_of(json_of(transport_->get(id_path("/v1/aerosols", id))));
}

Fit Client::create_fit(const FitRequest& request) const {
  return detail::fit_of(
      json_of(transport_->post_json("/v1/fits", detail::fit_request_json(request).dump())));
}

Fit Client::fit(std::int64_t id) const {
  return detail::fit_of(json_of(transport_->get(id_path("/v1/fits", id))));
}

Page<Fit> Client::fits(const PageRequest& page) const {
  QueryText query;
  add_page(query, page);
  return page_of<Fit>(transport_->get(query.target("/v1/fits")), detail::fit_of);
}

Fit Client::wait_for_fit(std::int64_t id, const WaitOptions& wait) const {
  const Fit final_state = poll<Fit>(
      wait, "fit " + std::to_string(id), [&] { return fit(id); },
      [](const Fit& state) { return state.done(); });
  if (final_state.status != "succeeded") {
    throw Error(0, "fit_" + final_state.status,
                "fit " + std::to_string(id) + " " + final_state.status + ": " +
                    final_state.error.value_or(""));
  }
  return final_state;
}

Job Client::create_job(const JobRequest& request) const {
  return detail::job_of(
      json_of(transport_->post_json("/v1/jobs", detail::job_request_json(request).dump())));
}

Page<Job> Client::jobs(const PageRequest& page) const {
  QueryText query;
  add_page(query, page);
  return page_of<Job>(transport_->get(query.target("/v1/jobs")), detail::job_of);
}

Job Client::job(std::int64_t id) const {
  return detail::job_of(json_of(transport_->get(id_path("/v1/jobs", id))));
}

Job Client::pause_job(std::int64_t id) const {
  return detail::job_of(json_of(transport_->post_empty(id_path("/v1/jobs", id) + "/pause")));
}

Job Client::resume_job(std::int64_t id) const {
  return detail::job_of(json_of(transport_->post_empty(id_path("/v1/jobs", id) + "/resume")));
}

std::int64_t Client::delete_job(std::int64_t id) const {
  return detail::member<std::int64_t>(json_of(transport_->remove(id_path("/v1/jobs", id))),
                                      "deleted");
}

}  // namespace clearsky::client
