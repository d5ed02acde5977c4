// A job's re-fit (job_refit.h).
#include "api/jobs/job_refit.h"

#include <algorithm>

#include "api/encode/fit_json.h"
#include "api/error/api_error.h"
#include "api/fits/fits_api.h"
#include "storage/repositories/fit_repository.h"

namespace clearsky::api {
namespace {

constexpr const char* kRefit = "refit";

// The error of the POST /v1/fits parser renamed to the job's member: "model" -> "refit.model".
ApiError renamed(const ApiError& error) {
  const std::string& parameter = error.parameter();
  const std::string member = parameter.empty() || parameter == "body"
                                 ? std::string(kRefit)
                                 : std::string(kRefit) + "." + parameter;
  const std::string prefix = parameter + ": ";
  const std::string what = error.what();
  const std::string reason = what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
  return ApiError::about(error.status(), error.code(), member, reason);
}

FitRequest parse_refit_body(storage::Database& db, nlohmann::json body, const std::string& dataset,
                            const std::string& software_version) {
  body["dataset"] = dataset;
  try {
    return parse_fit_request(db, body.dump(), software_version);
  } catch (const ApiError& e) {
    throw renamed(e);
  }
}

}  // namespace

FitRequest parse_job_refit(storage::Database& db, const nlohmann::json& refit,
                           const std::string& dataset, const std::vector<std::string>& models,
                           const nlohmann::json& parameters, const std::string& software_version) {
  if (!refit.is_object())
    throw invalid_parameter(kRefit, "must be an object: the body of POST /v1/fits without dataset");
  if (refit.contains("dataset"))
    throw invalid_parameter("refit.dataset", "a job re-fits its own dataset: leave it out");
  FitRequest request = parse_refit_body(db, refit, dataset, software_version);
  const bool all = models.size() == 1 && models[0] == "all";
  if (!all && std::find(models.begin(), models.end(), request.model) == models.end())
    throw invalid_parameter("refit.model", "'" + request.model + "' is not among the job's models");
  if (parameters.is_object()) {
    for (const FreeParameter& free : check_fit_request(request).settings.parameters)
      if (parameters.contains(free.name))
        throw conflicting_parameters("refit", "parameters." + free.name + " (the fit sets it)");
  }
  return request;
}

FitRequest job_fit_request(storage::Database& db, const storage::JobRecord& job,
                           const std::string& dataset, const std::string& software_version) {
  if (dataset.empty())
    throw std::invalid_argument("job " + job.name + ": its dataset no longer exists");
  return parse_refit_body(db, nlohmann::json::parse(job.refit), dataset, software_version);
}

nlohmann::ordered_json last_fit_json(storage::Database& db, const storage::JobRecord& job) {
  if (!job.last_fit_id) return nullptr;
  const auto record = storage::FitRepository(db).get(*job.last_fit_id);
  if (!record) return nullptr;
  const nlohmann::json fit = fit_to_json(*record, false);
  const auto member = [&fit](const char* name) {
    return fit.contains(name) ? nlohmann::ordered_json(fit[name]) : nlohmann::ordered_json();
  };
  return {{"id", record->id},
          {"status", record->fit.status},
          {"rmse_after", member("rmse_after")},
          {"values", member("values")},
          {"error", member("error")}};
}

}  // namespace clearsky::api
