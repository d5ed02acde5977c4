// /v1/evaluations, transport-free: the request body of POST (what to run), the list of stored
// runs with filters, and one run with its per-capture results and its comparison with the
// history (docs/data-api.md "Evaluations"). JSON:
//   POST body: {"models": ["preetham", ...] or "all", "dataset": NAME,
//               "parameters": {"turbidity": 3, "alpha": 1.3, ...}} (parameters optional; names
//               as the query parameters of the sky endpoints: atmosphere parameters and model
//               options). Each parameter applies to the requested models whose descriptor lists
//               it and only to them; one that none of them lists is refused (400 naming it), as
//               the sky endpoints refuse it.
//   list:  [{"id", "dataset", "model", "status", "started", "finished", "rmse", "job"}], newest
//          (highest id) first; filters model, dataset, since, until (ISO 8601, on the start
//          time), status, job (or job_id), applied before the page's limit (list_page.h)
//   show:  {"id", "dataset", "model", "model_version", "parameters" (an object: the
//           parameters applied to this model, as given), "software_version",
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
// configuration (the model's full configuration key, so that a parameter given at its default
// value compares with a run that left it out) and wavelength range (rmse_changed: relative
// difference above 1e-9; null when there is no such run or this run did not succeed). RMSE in
// mW/(m2.sr.nm), angles in degrees. Errors are ApiError (400 body or parameter, 404 unknown
// run, dataset or model).
// Thread-safety: each call uses the given Database from the calling thread only.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>

#include "api/encode/evaluation_json.h"
#include "api/evaluation/evaluation_runner.h"
#include "api/paging/list_page.h"
#include "api/request/parameters.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

// Parses and checks a POST body against the models available and the stored datasets (so that
// a bad request is refused before it is queued).
EvaluationRequest parse_evaluation_request(storage::Database& db, const std::string& body,
                                           std::span<const ModelFactory> available,
                                           const std::string& software_version);
// The parameters object of a body, a job or `clearsky evaluate --parameters`, checked against
// the requested models and returned as given (400 naming the parameter when no requested
// model lists it, when it is not a number ("grass" for albedo) or out of the range of a model
// that takes it): atmosphere parameters (alpha, beta, g, turbidity, albedo, ...) and model
// options (e.g. Bruneton's table sizes, Preetham's clamp_negative_fit) alike. With `models`
// empty only the types are checked (a stored job, checked when it was created; each model
// checks its configuration again when it is built).
nlohmann::json parse_evaluation_parameters(const nlohmann::json& parameters,
                                           std::span<const ModelFactory* const> models = {});

struct EvaluationFilter {
  std::optional<std::string> model;
  std::optional<std::string> dataset;
  std::optional<double> since_unix_s;  // started at or after
  std::optional<double> until_unix_s;  // started before
  std::optional<std::string> status;
  std::optional<std::int64_t> job_id;
  PageRequest page;  // limit and cursor: which part of the filtered list
};
// model, dataset, since, until, status, job (or job_id), limit and cursor from query parameters
// (400 for others).
EvaluationFilter parse_evaluation_filter(Parameters query);

struct ShowEvaluationOptions {
  SampleDetail samples = SampleDetail::none;
  std::optional<std::string> capture;  // one capture by label
};
// samples (true, false, spectra) and capture from query parameters (400 for others).
ShowEvaluationOptions parse_show_evaluation_options(Parameters query);

ListPage list_evaluations(storage::Database& db, const EvaluationFilter& filter);
nlohmann::ordered_json show_evaluation(storage::Database& db, std::int64_t run_id,
                                       const ShowEvaluationOptions& options = {});

// A run id from a path segment (400 when not a positive integer).
std::int64_t parse_id(const std::string& text, const std::string& parameter);

}  // namespace clearsky::api
