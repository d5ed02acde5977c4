// Atmosphere fits as JSON (docs/fits.md "The answer"): what the fits table stores
// (storage/repositories/fit_repository.h) and what `clearsky fit --json`, GET /v1/fits and
// GET /v1/fits/{id} answer, made from the stored record so that the CLI and the API agree.
// RMSE in mW/(m2.sr.nm); an RMSE the model could not give (a capture it answered nowhere) is
// null, never NaN.
#pragma once

#include <nlohmann/json.hpp>
#include <span>

#include "models/fitting/atmosphere_fit.h"
#include "storage/repositories/fit_repository.h"

namespace clearsky::api {

// [{"name", "min", "max", "grid_points"}].
nlohmann::json free_parameters_json(std::span<const FreeParameter> parameters);

// The stored form of a finished fit.
storage::FitOutcome fit_outcome(const FitResult& result);

// A stored fit: id, dataset, model, version, status, progress, stage, the request (free
// parameters, fixed parameters, search options, captures, settings) and, when it succeeded,
// the results; history (every point evaluated) only with_history.
nlohmann::json fit_to_json(const storage::FitRecord& record, bool with_history);

}  // namespace clearsky::api
