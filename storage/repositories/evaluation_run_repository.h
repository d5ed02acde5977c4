// Evaluation runs of a model against a dataset: what was run (model id and version, the full
// parameter set, the software version, the wavelength range, the processing steps applied to
// the measurements), when, how it ended, the total RMSE and timings, and the result of every
// capture (sun angles used, RMSE) with, from schema version 2, the compared wavelengths and
// each capture's per-sample errors (sample_errors_blob.h; identical blobs stored once). A run
// is recorded as 'running' when it starts so that a crash leaves a trace. From schema version
// 4 a run's parameters are JSON text (those applied to its model, as given) and its
// configuration key is kept apart for the history comparison; ids are never reused and a run
// keeps its job id after the job is deleted. From schema version 5 a run records how it handled
// the samples its model could not answer (exclude or clamp), how many samples its RMSE covers,
// the samples left out or clamped per capture (compared_samples.h), and a capture of which the
// model answered no sample has no RMSE. SQL on these tables lives only here.
// Thread-safety: as the Database.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "storage/repositories/compared_samples.h"
#include "storage/repositories/keyset_page.h"
#include "storage/repositories/sample_errors_blob.h"
#include "storage/sqlite/database.h"

namespace clearsky::storage {

struct RunCaptureResult {
  std::int64_t capture_id = 0;
  std::string capture_label;      // filled when read
  double capture_time_utc_s = 0;  // filled when read
  int utc_offset_minutes = 0;     // filled when read
  double sun_zenith_deg = 0;
  double sun_azimuth_deg = 0;
  double rmse = 0;  // mW/(m2.sr.nm); NaN when read for an unanswered capture
  std::int64_t values_compared = 0;
  // Written by finish() when present; read by get(id, true), empty for runs stored without.
  std::optional<SampleErrorTable> samples = std::nullopt;
  bool answered = true;  // false: the model answered no sample of the capture (no RMSE)
  // The samples compared (unknown for runs stored before per-sample errors were kept).
  std::optional<std::int64_t> samples_compared = std::nullopt;
  std::vector<SampleHandling> out_of_domain = {};  // samples left out or clamped, by reason
};

struct NewRun {
  std::int64_t dataset_id = 0;
  std::optional<std::int64_t> job_id;
  std::string model_id;
  std::string model_version;
  std::string parameters = "{}";  // JSON object: the parameters applied to the model, as given
  std::string configuration;      // the model's ModelConfig::canonical_string()
  std::string software_version;
  double min_wavelength_nm = 360;
  double max_wavelength_nm = 720;
  std::string out_of_domain = "exclude";  // what was done with samples the model cannot answer
};

struct RunRecord {
  std::int64_t id = 0;
  std::int64_t dataset_id = 0;
  std::optional<std::int64_t> job_id;
  std::string model_id, model_version;
  std::string parameters;     // JSON object text
  std::string configuration;  // ModelConfig::canonical_string()
  std::string software_version;
  double min_wavelength_nm = 0, max_wavelength_nm = 0;
  std::string started_utc;
  std::optional<std::string> finished_utc;
  std::string status;  // running, succeeded, failed
  std::optional<std::string> error;
  std::optional<double> rmse, precompute_seconds, evaluate_seconds;
  std::string out_of_domain;  // exclude or clamp
  // Over all captures (written by finish(); unknown for runs without per-sample records).
  std::optional<std::int64_t> samples_compared, samples_excluded, samples_clamped,
      captures_unanswered;
  std::optional<std::string> compared_samples;  // compared_samples_key() of the run
  std::string processing_steps;                 // one step per line
  // The compared wavelengths (columns of the per-sample errors); empty for runs stored before
  // schema version 2 and runs not finished.
  std::optional<std::vector<double>> wavelengths_nm;
  std::vector<RunCaptureResult> captures;  // filled by get()
};

// Filters of list(); each unset one keeps every run.
struct RunFilter {
  std::optional<std::int64_t> dataset_id;
  std::optional<std::string> model_id;
  std::optional<std::string> status;
  std::optional<std::int64_t> job_id;
  std::optional<double> since_unix_s;  // started at or after
  std::optional<double> until_unix_s;  // started before
};

class EvaluationRunRepository {
 public:
  explicit EvaluationRunRepository(Database& db) : db_(db) {}
  std::int64_t start(const NewRun& run);
  // Records success with the per-capture results, their per-sample errors when given and the
  // compared wavelengths (in one transaction), and the run's sample counts and compared-samples
  // key from the captures. A non-finite rmse (no capture answered) is stored as none. Throws
  // std::invalid_argument when a capture's sample errors do not have one column per
  // wavelength.
  void finish(std::int64_t run_id, double rmse, double precompute_seconds, double evaluate_seconds,
              const std::string& processing_steps, const std::vector<RunCaptureResult>& captures,
              std::span<const double> wavelengths_nm = {});
  void fail(std::int64_t run_id, const std::string& error);
  // Marks every run still 'running' as failed with this error (at start-up: runs a crash
  // interrupted); returns how many.
  int fail_unfinished(const std::string& error);
  // A run with its per-capture results; with_samples also reads their per-sample errors.
  std::optional<RunRecord> get(std::int64_t run_id, bool with_samples = false);
  // Runs of a dataset, newest first, without per-capture results.
  std::vector<RunRecord> list(std::int64_t dataset_id);
  // At most limit runs passing the filter, newest (highest id) first, with ids below before_id
  // when given; without per-capture results.
  KeysetPage<RunRecord> list(const RunFilter& filter, std::int64_t limit,
                             std::optional<std::int64_t> before_id = std::nullopt);
  // The newest succeeded run with an RMSE before this one of the same dataset, model,
  // configuration, wavelength range, out-of-domain handling and compared samples (the history
  // comparison's "like with like").
  std::optional<RunRecord> previous_like(const RunRecord& run);

 private:
  Database& db_;
};

}  // namespace clearsky::storage
