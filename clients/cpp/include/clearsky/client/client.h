// clearsky::client::Client: the clearsky HTTP API v1 from C++ (docs/http-api.md,
// docs/data-api.md; docs/clients.md "C++" shows it in use). One method per operation of the
// route table (api/routes/route_table.cpp), with typed requests and answers (sky_types.h,
// data_types.h); every refusal is a clearsky::client::Error (error.h) naming the parameter.
//
// Retries: an answer 503 or 429 that carries Retry-After (tables being built, a full queue, too
// many table builds) is asked again after that many seconds, at most max_retries times and only
// when Retry-After is at most max_retry_wait_s; otherwise, and for every other error, Error is
// thrown at once. Writes are retried too: a 503 or 429 means the server did nothing.
//
// Thread-safety: a Client may be used from several threads at once; each request opens its own
// connection, and the options are read-only after construction. on_retry may then be called
// from those threads at once.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "clearsky/client/data_types.h"
#include "clearsky/client/error.h"
#include "clearsky/client/sky_types.h"

namespace clearsky::client {

// Told before the client waits to ask again (for logging).
struct RetryNotice {
  int attempt = 0;  // the attempt that was refused, from 1
  int status = 0;   // 503 or 429
  std::string code;
  int wait_s = 0;  // the answer's Retry-After
};

struct ClientOptions {
  std::string base_url = "http://127.0.0.1:8080";  // scheme://host[:port], https too
  std::string token;  // the bearer token of the writes (--token of the server); empty: none
  int connect_timeout_s = 10;
  int read_timeout_s = 120;  // a large skydome or batch is computed while it is sent
  int write_timeout_s = 120;
  int max_retries = 3;
  int max_retry_wait_s = 60;
  std::function<void(const RetryNotice&)> on_retry;
};

class HttpTransport;

class Client {
 public:
  explicit Client(ClientOptions options = {});
  ~Client();
  Client(Client&&) noexcept;
  Client& operator=(Client&&) noexcept;
  Client(const Client&) = delete;
  Client& operator=(const Client&) = delete;

  // Service: true when /healthz answers; /readyz's status ("ready"; Error 503 not_ready while
  // the default tables are being built, when the retries are spent).
  bool healthy() const;
  std::string readiness() const;

  // Sky.
  std::vector<ModelInfo> models() const;
  SunPosition sun(const SunRequest& request) const;
  RadianceResult radiance(const RadianceRequest& request) const;
  RadianceResult radiance(const RadianceBatchRequest& request) const;
  IrradianceResult irradiance(const IrradianceRequest& request) const;
  IrradianceSeriesResult irradiance_series(const IrradianceSeriesRequest& request) const;
  RgbResult rgb(const RgbRequest& request) const;
  RgbResult rgb(const RgbBatchRequest& request) const;
  // The image is written to `out` chunk by chunk as it arrives, never held whole. A refusal
  // (before any byte is written) is an Error; a connection lost midway is an Error after part
  // of the image was written.
  SkydomeDownload skydome(const SkydomeRequest& request, std::ostream& out) const;
  // The same into a file: written to "<file>.part" and renamed to `file` once complete, so a
  // failed download leaves no file behind.
  SkydomeDownload skydome_to_file(const SkydomeRequest& request,
                                  const std::filesystem::path& file) const;
  SkyPatchesResult sky_patches(const SkyPatchesRequest& request) const;
  // A sky matrix: one sky vector per step (docs/building-energy.md "Sky matrices").
  SkyMatrixResult sky_matrix(const SkyMatrixRequest& request) const;

  // Datasets (writes need the token).
  Page<DatasetSummary> datasets(const PageRequest& page = {}) const;
  Dataset dataset(const std::string& name, const DatasetQuery& query = {}) const;
  // Streams the archive from its file (never read whole) and answers the queued import;
  // follow it with wait_for_import.
  ImportState upload_dataset(const DatasetUpload& upload,
                             const UploadProgress& progress = {}) const;
  // Answers the name deleted.
  std::string delete_dataset(const std::string& name) const;

  // Imports.
  Page<ImportState> imports(const ImportFilter& filter = {}) const;
  ImportState import_state(std::int64_t id) const;
  ImportState wait_for_import(std::int64_t id, const WaitOptions& wait = {}) const;

  // Evaluations.
  EvaluationTicket create_evaluation(const EvaluationRequest& request) const;
  EvaluationTicket evaluation_ticket(std::int64_t ticket) const;
  EvaluationTicket wait_for_ticket(std::int64_t ticket, const WaitOptions& wait = {}) const;
  Evaluation evaluation(std::int64_t id, const EvaluationQuery& query = {}) const;
  Page<EvaluationSummary> evaluations(const EvaluationFilter& filter = {}) const;

  // Fits (docs/fits.md; creating one needs the token): the answer to create_fit is the queued
  // fit; follow it with wait_for_fit, which throws an Error (code "fit_failed" or
  // "fit_interrupted") when the fit did not succeed.
  Fit create_fit(const FitRequest& request) const;
  Fit fit(std::int64_t id) const;
  Page<Fit> fits(const PageRequest& page = {}) const;
  Fit wait_for_fit(std::int64_t id, const WaitOptions& wait = {}) const;

  // Users' AERONET inversions for measured_aerosols (docs/data-api.md "Aerosol inversions";
  // uploading needs the token): the .pfn file is sent from its path, read whole by the server
  // before it is stored (400 naming "body" when refused).
  AerosolInversion upload_aerosols(const std::string& name,
                                   const std::filesystem::path& file) const;
  Page<AerosolInversion> aerosol_inversions(const PageRequest& page = {}) const;
  AerosolInversion aerosol_inversion(std::int64_t id) const;

  // Jobs.
  Job create_job(const JobRequest& request) const;
  Page<Job> jobs(const PageRequest& page = {}) const;
  Job job(std::int64_t id) const;
  Job pause_job(std::int64_t id) const;
  Job resume_job(std::int64_t id) const;
  // Answers the id deleted.
  std::int64_t delete_job(std::int64_t id) const;

 private:
  std::unique_ptr<HttpTransport> transport_;
};

}  // namespace clearsky::client
