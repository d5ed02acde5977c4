// /v1/evaluations, transport-free: the request body of POST (what to run), the list of stored
// runs with filters, and one run with its per-capture results and its comparison with the
// history (docs/http-api.md). JSON:
//   POST body: {"models": ["preetham", ...] or "all", "dataset": NAME,
//               "parameters": {"turbidity": 3, "alpha": 1.3, ...}} (parameters optional; names
//               as the query parameters of the sky endpoints; applied to every model)
//   list:  [{"id", "dataset", "model", "status", "started", "finished", "rmse", "job"}], newest
//          first; filters model, dataset, since, until (ISO 8601, on the start time), status
//   show:  {"id", "dataset", "model", "model_version", "parameters", "software_version",
//           "wavelength_range_nm", "job", "status", "error", "started", "finished", "rmse",
//           "timings": {"precompute_seconds", "evaluate_seconds"}, "processing_steps": [...],
//           "captures": [{"label", "time", "sun_zenith", "sun_azimuth", "rmse",
//           "values_compared"}], "history": {"previous_run", "previous_rmse", "rmse_changed"}}
//          samples=true adds to each capture "samples": [{"index", "view_zenith", "view_azimuth",
//          "rmse", "bias"}] (null for runs stored before per-sample errors were kept, schema
//          version 1); samples=spectra also adds each sample's "errors" (model - measured) and
//          the run's "wavelengths_nm" after "wavelength_range_nm" (null likewise); capture=LABEL
//          keeps that capture only (404 when the run has none of that label). Without samples
//          the answer is as before (api/encode/evaluation_json.h for the sample values).
// "history" compares with the newest earlier succeeded run of the same dataset, model,
// parameters and wavelength range (rmse_changed: relative difference above 1e-9; null when
// there is no such run or this run did not succeed). RMSE in mW/(m2.sr.nm), angles in degrees.
// Errors are ApiError (400 body or parameter, 404 unknown run, dataset or model).
// Thread-safety: each call uses the given Database from the calling thread only.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>

#include "api/encode/evaluation_json.h"
#include "api/evaluation/evaluation_runner.h"
#include "api/request/parameters.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

// Parses and checks a POST body against the models available and the stored datasets (so that
// a bad request is refused before it is queued).
EvaluationRequest parse_evaluation_request(storage::Database& db, const std::string& body,
                                           std::span<const ModelFactory> available,
                                           const std::string& software_version);
// The parameters object of a body or a job applied to the default configuration (400 naming
// the parameter when unknown, not a number or out of range): the shared atmosphere parameters,
// and the options of the requested models (e.g. Bruneton's table sizes, Nishita93's
// study_viewer_sample, Preetham's clamp_negative_fit), each applied to the models that list it
// (options_for_model). With `models` empty, options are not checked here (a stored job, checked
// when it was created; the model checks them again when it is built).
ModelConfig parse_evaluation_parameters(const nlohmann::json& parameters,
                                        std::span<const ModelFactory* const> models = {});

struct EvaluationFilter {
  std::optional<std::string> model;
  std::optional<std::string> dataset;
  std::optional<double> since_unix_s;  // started at or after
  std::optional<double> until_unix_s;  // started before
  std::optional<std::string> status;
  std::optional<std::int64_t> job_id;
};
// model, dataset, since, until, status from query parameters (400 for others).
EvaluationFilter parse_evaluation_filter(Parameters query);

struct ShowEvaluationOptions {
  SampleDetail samples = SampleDetail::none;
  std::optional<std::string> capture;  // one capture by label
};
// samples (true, false, spectra) and capture from query parameters (400 for others).
ShowEvaluationOptions parse_show_evaluation_options(Parameters query);

nlohmann::ordered_json list_evaluations(storage::Database& db, const EvaluationFilter& filter);
nlohmann::ordered_json show_evaluation(storage::Database& db, std::int64_t run_id,
                                       const ShowEvaluationOptions& options = {});

// A run id from a path segment (400 when not a positive integer).
std::int64_t parse_id(const std::string& text, const std::string& parameter);

}  // namespace clearsky::api
