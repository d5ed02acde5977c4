// A job that re-fits its dataset (docs/data-api.md "Jobs", docs/fits.md "In evaluations and
// jobs"): its optional `refit` member is the body of POST /v1/fits without the dataset (the
// job's), checked at creation by the parser of POST /v1/fits (api/fits/fits_api.h) with the
// same refusals, each naming `refit.<member>`. At each occurrence the scheduler
// (server/scheduler) runs that fit with run_fit (api/fits/fit_runner.h), stored as any fit, and
// then evaluates the job's models with `"fit"` = the new fit's id, which applies to the fitted
// model only.
// Thread-safety: each call uses the given Database from the calling thread only.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "api/fits/fit_runner.h"
#include "storage/repositories/job_repository.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

// The job's refit member checked against its dataset, its models ("all" or ids) and its
// evaluation parameters (null when none): 400 naming `refit.<member>` for what POST /v1/fits
// refuses; `refit.dataset` (the job's dataset is fitted); `refit.model` when the job does not
// evaluate that model; 400 conflicting_parameters naming `refit` when the evaluation parameters
// give a parameter the fit frees (the new fit sets it). The job's create_job refuses `fit` in
// its parameters together with refit before checking them.
FitRequest parse_job_refit(storage::Database& db, const nlohmann::json& refit,
                           const std::string& dataset, const std::vector<std::string>& models,
                           const nlohmann::json& parameters, const std::string& software_version);

// The fit an occurrence of the job runs (its stored refit on its dataset, by name); throws
// std::invalid_argument when its dataset is gone, ApiError when the request no longer parses.
FitRequest job_fit_request(storage::Database& db, const storage::JobRecord& job,
                           const std::string& dataset, const std::string& software_version);

// The job's last_fit: {"id", "status", "rmse_after", "values", "error"} of the fit its newest
// occurrence made ("rmse_after" and "values" null until it succeeded, "error" null unless it
// failed or was interrupted); null before the first occurrence, for a job that does not re-fit,
// or once the fit is gone with its dataset.
nlohmann::ordered_json last_fit_json(storage::Database& db, const storage::JobRecord& job);

}  // namespace clearsky::api
