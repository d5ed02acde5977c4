// The fit parameter of evaluations, scheduled jobs and `clearsky evaluate --parameters`
// (docs/data-api.md "Evaluation parameters", docs/fits.md "Using a fit"): "fit": ID (a number or
// its text), "latest" or "latest:DATASET", as the sky endpoints' fit= (api/request/sky_fit.h).
// A fit by id applies to its own model and only to it (as a parameter applies to the models
// that list it); latest applies to every requested model, each its own newest succeeded fit.
// The fit is expanded when a model's run starts: a job with "fit": "latest" evaluates with the
// newest fit at each occurrence. The run's stored parameters are the expanded ones, "fit" being
// the id used, so that its history shows which fit and which values each run had.
// Thread-safety: pure functions of their arguments; each uses the given Database from the
// calling thread only.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <span>

#include "api/fits/stored_fit_values.h"
#include "models/core/model_factory.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

// The fit the parameters name; nullopt without "fit". 400 naming fit for a value that is
// neither a positive integer nor a string parse_fit_reference reads.
std::optional<FitReference> evaluation_fit_reference(const nlohmann::json& parameters);

// The parameters of the model's run: `parameters` without "fit" when there is none or it is a
// fit of another model (by id); otherwise with the fit's values added and "fit" set to its id.
// 400 conflicting_parameters naming a parameter the parameters give and the fit sets; the
// refusals of find_applied_fit (404 unknown_fit, 409 fit_not_succeeded) naming fit.
nlohmann::json expand_evaluation_fit(storage::Database& db, const nlohmann::json& parameters,
                                     const ModelDescriptor& descriptor);

// The checks of a new evaluation or job (before it is queued or stored): a fit by id must be of
// one of the models (409 fit_model_mismatch naming fit), latest must find a fit for each of them
// (404 unknown_fit), and each model's expanded parameters must be in its ranges (400 naming the
// parameter) and a valid configuration.
void check_evaluation_fit(storage::Database& db, const nlohmann::json& parameters,
                          std::span<const ModelFactory* const> models);

}  // namespace clearsky::api
