// The fit parameter of evaluations (evaluation_fit.h).
#include "api/evaluation/evaluation_fit.h"

#include <string>

#include "api/error/api_error.h"
#include "api/evaluation/evaluation_runner.h"
#include "api/evaluation/evaluations_api.h"

namespace clearsky::api {

std::optional<FitReference> evaluation_fit_reference(const nlohmann::json& parameters) {
  if (!parameters.is_object() || !parameters.contains(kFitParameter)) return std::nullopt;
  const nlohmann::json& value = parameters[kFitParameter];
  if (value.is_number_integer()) return parse_fit_reference(std::to_string(value.get<long long>()));
  if (value.is_string()) return parse_fit_reference(value.get<std::string>());
  throw invalid_parameter(kFitParameter,
                          "must be a fit id (a positive integer), \"latest\" or "
                          "\"latest:DATASET\"");
}

nlohmann::json expand_evaluation_fit(storage::Database& db, const nlohmann::json& parameters,
                                     const ModelDescriptor& descriptor) {
  const std::optional<FitReference> reference = evaluation_fit_reference(parameters);
  if (!reference) return parameters;
  nlohmann::json out = parameters;
  out.erase(kFitParameter);
  // A fit by id of another model leaves this model's run as if it had not been named.
  if (reference->id && find_succeeded_fit(db, *reference->id).model_id != descriptor.id) return out;
  const AppliedFit fit = find_applied_fit(db, *reference, descriptor);
  require_fit_parameters_listed(fit, descriptor);
  for (const auto& [name, value] : fit.values) {
    if (out.contains(name)) throw parameter_set_by_fit(name, fit);
    out[name] = value;
  }
  out[kFitParameter] = fit.id;
  return out;
}

void check_evaluation_fit(storage::Database& db, const nlohmann::json& parameters,
                          std::span<const ModelFactory* const> models) {
  const std::optional<FitReference> reference = evaluation_fit_reference(parameters);
  if (!reference) return;
  if (reference->id) {
    const AppliedFit fit = find_succeeded_fit(db, *reference->id);
    std::string ids;
    bool requested = false;
    for (const ModelFactory* model : models) {
      requested = requested || model->descriptor->id == fit.model_id;
      ids += (ids.empty() ? "" : ", ") + model->descriptor->id;
    }
    if (!requested) {
      throw ApiError::about(409, "fit_model_mismatch", kFitParameter,
                            "fit " + std::to_string(fit.id) + " is a fit of " + fit.model_id +
                                ", which is not among the requested models (" + ids + ")");
    }
  }
  for (const ModelFactory* model : models) {
    const ModelDescriptor& descriptor = *model->descriptor;
    const nlohmann::json expanded = expand_evaluation_fit(db, parameters, descriptor);
    if (!expanded.contains(kFitParameter)) continue;
    // The fit's values alone, checked as given parameters of this model (its descriptor's
    // ranges), then the model's whole configuration.
    nlohmann::json values = nlohmann::json::object();
    for (const auto& [name, value] : expanded.items()) {
      if (name != kFitParameter && !parameters.contains(name)) values[name] = value;
    }
    const ModelFactory* const alone[] = {model};
    parse_evaluation_parameters(values, alone);
    try {
      validate_config(descriptor, config_for_model(descriptor, expanded));
    } catch (const std::invalid_argument& e) {
      throw from_invalid_argument(e);
    }
  }
}

}  // namespace clearsky::api
