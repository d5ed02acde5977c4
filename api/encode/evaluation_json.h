// JSON of evaluation results, as DESIGN.md "CLI contract" fixes it for `clearsky evaluate
// --json` (and the API reuses): {"dataset", "wavelength_range_nm": [min, max], "models": [{
// "model", "rmse", "captures": [{"time", "sun_zenith", "sun_azimuth", "rmse"}],
// "precompute_seconds", "evaluate_seconds"}]}; RMSE in mW/(m2.sr.nm), angles in degrees, time
// ISO 8601 with the site's offset. Keys keep the contract's order. A non-finite number is an error, never a JSON null.
#pragma once

#include <nlohmann/json.hpp>

#include "api/evaluation/evaluation_runner.h"
#include "storage/repositories/dataset_repository.h"

namespace clearsky::api {

nlohmann::ordered_json evaluation_to_json(const EvaluationReport& report);
// [{"name", "captures", "samples"}, ...]
nlohmann::ordered_json datasets_to_json(const std::vector<storage::DatasetSummary>& datasets);

}  // namespace clearsky::api
