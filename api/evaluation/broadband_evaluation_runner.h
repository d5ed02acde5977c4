// An evaluation run on a broadband irradiance dataset (docs/data-api.md "Evaluations of
// broadband irradiance"), as `clearsky evaluate` starts it: each requested model's broadband
// GHI, DHI and DNI at every measured instant against the measurement (broadband_evaluation.h),
// each run recorded as an evaluation_runs row (its rmse the RMSE over the components measured,
// W/m2, all their samples pooled) with its per-component results
// (storage/repositories/irradiance_run_results.h). Parameters as run_evaluation
// (evaluation_runner.h). Models "all" are the registered models with a broadband answer;
// naming one without (broadband_unavailable_reason: Preetham, Hosek-Wilkie) is refused before
// anything runs: ApiError 422 broadband_unavailable naming `models`. A stored fit in the
// parameters ("fit") is expanded when each model's run starts, as for captures
// (evaluation_fit.h); the run's processing steps say at which altitude the model answered
// (broadband_model_altitude.h) and how averaged samples were compared
// (averaging_period_quadrature.h).
// Thread-safety: uses the given Database from the calling thread only.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "api/evaluation/broadband_evaluation.h"
#include "api/evaluation/evaluation_runner.h"

namespace clearsky::api {

struct BroadbandModelRun {
  std::int64_t run_id = 0;
  std::string model_id;
  std::optional<double> rmse_w_m2;  // pooled over the components measured
  std::vector<BroadbandComponentResult> components;
  std::int64_t samples = 0, samples_sun_up = 0;
  double precompute_seconds = 0, evaluate_seconds = 0;
};

struct BroadbandEvaluationReport {
  std::string dataset;
  std::vector<BroadbandModelRun> models;
};

// The requested factories, "all" being those with a broadband answer; ApiError 422
// broadband_unavailable naming `models` for one named that has none; std::invalid_argument for
// unknown ids (resolve_models).
std::vector<const ModelFactory*> broadband_models(const std::vector<std::string>& requested,
                                                  std::span<const ModelFactory> available);

// Whether the dataset exists and is of kind broadband_irradiance.
bool is_broadband_dataset(storage::Database& db, const std::string& dataset);

BroadbandEvaluationReport run_broadband_evaluation(storage::Database& db,
                                                   const EvaluationRequest& request,
                                                   std::span<const ModelFactory> available);

// {"dataset", "models": [{"model", "run", "rmse_w_m2", "samples", "samples_sun_up",
//  "components": [{"component", "rmse_w_m2", "mean_bias_w_m2", "samples_compared"}],
//  "precompute_seconds", "evaluate_seconds"}]}; with_errors adds each component's "errors_w_m2"
// (null where not compared).
nlohmann::ordered_json broadband_evaluation_json(const BroadbandEvaluationReport& report,
                                                 bool with_errors = false);

}  // namespace clearsky::api
