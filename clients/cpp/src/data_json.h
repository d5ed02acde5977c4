// The data endpoints' JSON (docs/data-api.md; the schemas Dataset, Import, EvaluationTicket,
// Evaluation and Job of /openapi.json): request bodies written, answers read into the typed
// results of data_types.h.
//
// Thread-safety: pure functions.
#pragma once

#include <nlohmann/json.hpp>

#include "clearsky/client/data_types.h"

namespace clearsky::client::detail {

nlohmann::json evaluation_request_json(const EvaluationRequest& request);
nlohmann::json job_request_json(const JobRequest& request);
nlohmann::json fit_request_json(const FitRequest& request);

DatasetSummary dataset_summary_of(const nlohmann::json& json);
Dataset dataset_of(const nlohmann::json& json);
ImportState import_state_of(const nlohmann::json& json);
EvaluationTicket ticket_of(const nlohmann::json& json);
EvaluationSummary evaluation_summary_of(const nlohmann::json& json);
Evaluation evaluation_of(const nlohmann::json& json);
Job job_of(const nlohmann::json& json);
Fit fit_of(const nlohmann::json& json);
AerosolInversion aerosol_inversion_of(const nlohmann::json& json);

}  // namespace clearsky::client::detail
