// The OpenAPI 3.0 description of the data endpoints (datasets, imports, evaluations, jobs;
// docs/http-api.md), added to the document of openapi_document.h. Errors refer to its Error schema.
#pragma once

#include <nlohmann/json.hpp>

namespace clearsky::api {

void add_data_paths(nlohmann::json& paths);

}  // namespace clearsky::api
