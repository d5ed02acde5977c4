// JSON of evaluation results for `clearsky evaluate --json` (docs/architecture.md "Command line"),
// which the API reuses: {"dataset", "wavelength_range_nm": [min, max], "models": [{"model",
// "rmse", "captures": [{"time", "sun_zenith", "sun_azimuth", "rmse"}], "precompute_seconds",
// "evaluate_seconds"}]}; RMSE in mW/(m2.sr.nm), angles in degrees, time ISO 8601 with the site's
// offset. Keys keep the contract's order. A non-finite number is an error, never a JSON null. On
// request each capture adds "samples" (SampleDetail::summary: [{"index", "view_zenith",
// "view_azimuth", "rmse", "bias"}]; SampleDetail::spectra adds each sample's "errors" at the
// model's "wavelengths_nm"), the values as stored with the run (storage/repositories/
// sample_errors_blob.h: RMSE and bias float64, angles and errors float32 written with the
// shortest decimal that reads back to the same float32), so that the CLI and the API
// (GET /v1/evaluations/{id}?samples=...) print the same numbers. Errors: model - measured,
// mW/(m2.sr.nm); angles in degrees, azimuth clockwise from North.
// Samples the model could not answer (docs/data-api.md "Samples a model cannot answer"): each
// model adds "out_of_domain" (exclude or clamp), "samples_compared" (what its RMSE covers),
// "samples_excluded", "samples_clamped" and "captures_unanswered" (its RMSE is null when no
// capture is answered); each capture adds "samples_compared", "excluded" and "clamped" ([{"reason",
// "count", "samples": [scan indices]}], by reason), and an unanswered capture has "rmse": null.
#pragma once

#include <nlohmann/json.hpp>

#include "api/evaluation/evaluation_runner.h"
#include "storage/repositories/dataset_repository.h"

namespace clearsky::api {

enum class SampleDetail { none, summary, spectra };

// The "samples" array of one capture.
nlohmann::ordered_json samples_to_json(const storage::SampleErrorTable& samples,
                                       SampleDetail detail);
// The "excluded" (handling "excluded") or "clamped" array of one capture.
nlohmann::ordered_json sample_handling_to_json(const std::vector<storage::SampleHandling>& stored,
                                               std::string_view handling);
// A float32 as the JSON number of its shortest round-tripping decimal (2.53f -> 2.53).
nlohmann::ordered_json float_to_json(float value);

nlohmann::ordered_json evaluation_to_json(const EvaluationReport& report,
                                          SampleDetail samples = SampleDetail::none);
// [{"name", "captures", "samples"}, ...]
nlohmann::ordered_json datasets_to_json(const std::vector<storage::DatasetSummary>& datasets);

}  // namespace clearsky::api
