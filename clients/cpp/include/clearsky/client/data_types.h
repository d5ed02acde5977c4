// The requests and answers of the data endpoints (docs/data-api.md): datasets, imports,
// evaluations and their tickets, jobs, and the pages of their lists. Times are the server's ISO
// 8601 texts; ids are the server's integers (never reused).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "clearsky/client/sky_types.h"

namespace clearsky::client {

// A page of a list (docs/data-api.md "Pagination"): next_cursor, when another page follows, is
// the opaque cursor to pass as PageRequest::cursor.
template <typename Item>
struct Page {
  std::vector<Item> items;
  std::optional<std::string> next_cursor;
};
struct PageRequest {
  std::optional<int> limit;  // 1..1000, server default 100
  std::optional<std::string> cursor;
};

// Datasets.
struct DatasetSummary {
  std::string name;
  std::string format;
  std::string created;
  std::int64_t captures = 0;
  std::int64_t samples = 0;
};
struct Place {
  double latitude_deg = 0;
  double longitude_deg = 0;
  double elevation_m = 0;
};
struct CaptureSample {
  std::int64_t index = 0;
  ViewDirection view;
  std::int64_t flags = 0;
  std::vector<double> wavelengths_nm;       // with DatasetQuery::capture
  std::vector<double> radiance_w_m2_sr_nm;  // with DatasetQuery::capture
};
struct Capture {
  std::string label;
  std::string time;
  std::string time_utc;
  Place place;
  std::optional<double> sun_zenith_deg, sun_azimuth_deg, sun_azimuth_estimated_deg;
  std::int64_t sample_count = 0;
  std::vector<CaptureSample> samples;  // with DatasetQuery::samples or ::capture
};
struct Dataset {
  std::string name;
  std::string format;
  std::string created;
  std::vector<Capture> captures;
};
struct DatasetQuery {
  bool samples = false;                // each capture's samples
  std::optional<std::string> capture;  // one capture, with its spectra
};
// POST /v1/datasets with an archive (.7z, zip, tar) read from a file and streamed.
struct DatasetUpload {
  std::string name;  // [A-Za-z0-9][A-Za-z0-9._-]{0,127}
  std::string format = "kider";
  std::filesystem::path archive;
};
// Called as the archive is sent: bytes sent so far and the archive's size. Returning false
// cancels the upload (Error with code "cancelled").
using UploadProgress = std::function<bool(std::uint64_t sent_bytes, std::uint64_t total_bytes)>;

// Imports.
struct ImportProgress {
  std::string phase;  // "reading", "writing", "committed"; empty while queued
  std::int64_t bytes_read = 0;
  std::optional<std::int64_t> bytes_total;
  std::int64_t entries_read = 0;
  std::optional<std::int64_t> entries_total;
  std::int64_t files_read = 0;
  std::int64_t captures_added = 0;
  std::int64_t samples_added = 0;
};
struct ImportReport {
  std::string dataset;
  std::vector<std::string> added;
  std::vector<std::string> unchanged;
  std::int64_t samples_added = 0;
  double seconds = 0;
};
struct ImportFailure {
  std::string code;
  std::string message;
};
struct ImportState {
  std::int64_t id = 0;
  std::string dataset;
  std::string format;
  std::string source;  // "upload" or "path"
  std::optional<std::string> path;
  std::optional<std::int64_t> upload_bytes;
  std::string status;  // "queued", "running", "succeeded", "failed"
  ImportProgress progress;
  std::optional<ImportReport> report;
  std::optional<ImportFailure> error;
  std::string location;
  bool finished() const { return status == "succeeded" || status == "failed"; }
};
struct ImportFilter : PageRequest {
  std::optional<std::string> status;
  std::optional<std::string> dataset;
};

// How Client::wait_for_import and wait_for_ticket poll: every poll_interval_ms until the
// state is final, at most timeout_ms (then Error with code "timeout").
struct WaitOptions {
  int poll_interval_ms = 200;
  int timeout_ms = 600000;
};

// Evaluations. models empty: "all" (every model the server serves).
struct EvaluationRequest {
  std::string dataset;
  std::vector<std::string> models;
  Parameters parameters;  // docs/data-api.md "Evaluation parameters"
};
struct TicketModel {
  std::string model;
  std::optional<std::int64_t> run;
  std::string status;  // "queued", "running", "succeeded", "failed", "skipped", "interrupted"
  std::optional<std::string> error;
};
struct EvaluationTicket {
  std::int64_t ticket = 0;
  std::string dataset;
  std::string status;  // "queued", "running", "succeeded", "failed", "interrupted"
  std::string created;
  std::optional<std::string> finished;
  std::vector<std::int64_t> runs;
  std::vector<TicketModel> models;
  std::optional<std::string> error;
  bool done() const { return status != "queued" && status != "running"; }
};
// One measured component of a broadband irradiance dataset against the model's broadband figure
// (docs/data-api.md "Evaluations of broadband irradiance"): W/m2, absent when no sample was
// compared; errors_w_m2 per sample by instant (absent where not compared) when the run was read
// with samples.
struct IrradianceComponentResult {
  std::string component;  // "ghi", "dhi" or "dni"
  std::optional<double> rmse_w_m2;
  std::optional<double> mean_bias_w_m2;  // model minus measured
  std::int64_t samples_compared = 0;
  std::vector<std::optional<double>> errors_w_m2;
};
struct EvaluationSummary {
  std::int64_t id = 0;
  std::string dataset;
  std::string model;
  std::string status;  // "running", "succeeded", "failed"
  std::string started;
  std::optional<std::string> finished;
  // The run's RMSE in its unit (rmse_unit): on captures mW/(m2.sr.nm), on a broadband
  // irradiance dataset W/m2 (all compared components pooled); the other one is absent.
  std::optional<double> rmse_mw_m2_sr_nm;
  std::optional<double> rmse_w_m2;
  std::optional<std::int64_t> samples_compared;
  std::vector<IrradianceComponentResult> irradiance_components;  // broadband datasets only
  std::optional<std::int64_t> job;
};
struct EvaluationFilter : PageRequest {
  std::optional<std::string> model, dataset, status, since, until;
  std::optional<std::int64_t> job;
};
struct EvaluationCapture {
  std::string label;
  std::string time;
  double sun_zenith_deg = 0;
  double sun_azimuth_deg = 0;
  std::optional<double> rmse_mw_m2_sr_nm;
  std::int64_t values_compared = 0;
  std::optional<std::int64_t> samples_compared;
};
struct Evaluation {
  std::int64_t id = 0;
  std::optional<std::string> dataset;
  std::string model;
  std::string model_version;
  Parameters parameters;  // as given to this run's model
  std::string software_version;
  std::vector<double> wavelength_range_nm;
  std::optional<std::int64_t> job;
  std::string status;
  std::optional<std::string> error;
  std::string started;
  std::optional<std::string> finished;
  // The paper's RMSE over 360..720 nm, mW/(m2.sr.nm) (README.md "Conventions"); on a broadband
  // irradiance dataset rmse_w_m2 instead (all compared components pooled) with each component.
  std::optional<double> rmse_mw_m2_sr_nm;
  std::optional<double> rmse_w_m2;
  std::vector<IrradianceComponentResult> irradiance_components;
  std::string out_of_domain;  // "exclude" or "clamp"
  std::optional<std::int64_t> samples_compared, samples_excluded, samples_clamped;
  std::vector<std::string> processing_steps;
  std::vector<EvaluationCapture> captures;
  // Open-ended in the API: precompute and evaluation seconds; the comparison with the previous
  // like run (docs/data-api.md "History comparison").
  nlohmann::json timings;
  nlohmann::json history;
};
struct EvaluationQuery {
  std::optional<std::string> samples;  // "true" or "spectra"
  std::optional<std::string> capture;
};

// Jobs: evaluations on a 5-field UTC cron schedule.
struct JobRequest {
  std::string name;
  std::string schedule;  // "0 3 * * *"
  std::string dataset;
  std::vector<std::string> models;  // empty: "all"
  Parameters parameters;
};
struct JobResult {
  std::int64_t run = 0;
  std::string model;
  std::string status;
  std::string started;
  std::optional<double> rmse_mw_m2_sr_nm;
};
struct Job {
  std::int64_t id = 0;
  std::string name;
  std::string schedule;
  std::string dataset;
  std::vector<std::string> models;  // empty: "all"
  Parameters parameters;
  bool paused = false;
  std::string created;
  std::optional<std::string> last_run;
  std::optional<std::string> next_run;
  std::vector<JobResult> last_result;
};

// POST /v1/fits (docs/fits.md "Over HTTP"): the options of `clearsky fit`.
struct FitRequest {
  std::string dataset;
  std::string model;
  std::vector<std::string> free;  // empty: the model's default free parameters
  // Per free parameter: [low, high]; absent: the descriptor's range.
  std::map<std::string, std::array<double, 2>> bounds;
  Parameters parameters;              // the fixed parameters (and "quality")
  std::vector<std::string> captures;  // capture labels; empty: all of the dataset
  bool per_capture = false;
  bool cross_validate = false;
  std::optional<int> max_evaluations;
};
// A fit's state; values and the RMSE (mW/(m2.sr.nm)) once it succeeded.
struct Fit {
  std::int64_t id = 0;
  std::string dataset;
  std::string model;
  std::string status;   // "queued", "running", "succeeded", "failed", "interrupted"
  double progress = 0;  // 0..1
  std::optional<std::string> stage;
  std::map<std::string, double> values;  // the fitted parameters
  std::optional<double> rmse_before, rmse_after, cross_validated_rmse;
  std::string created;
  std::optional<std::string> finished;
  std::optional<std::string> error;
  bool done() const { return status != "queued" && status != "running"; }
};

// One retrieval of a stored AERONET inversion (GET /v1/aerosols/{id}).
struct AerosolRetrieval {
  std::string date;      // as written, dd:mm:yyyy
  std::string time_utc;  // as written, hh:mm:ss
  double time_utc_h = 0;
  double aod_440 = 0;
  double angstrom_440_870 = 0;
  std::vector<double> aod;  // at each of AerosolInversion::wavelengths_nm
};
// A stored AERONET inversion for measured_aerosols (docs/data-api.md "Aerosol inversions");
// wavelengths_nm and retrievals are empty in a list's items.
struct AerosolInversion {
  std::int64_t id = 0;
  std::string name;
  std::string content_hash;  // 16 hex digits
  std::string site;
  std::string first_day, last_day;  // yyyy-mm-dd
  std::int64_t retrieval_count = 0;
  std::string created;
  std::vector<double> wavelengths_nm;
  std::vector<AerosolRetrieval> retrievals;
};

}  // namespace clearsky::client
