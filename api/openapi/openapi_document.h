// The OpenAPI 3.0 description of HTTP API v1, served at GET /openapi.json (docs/openapi.md):
// `paths` from the routes and their operationIds, each Operation Object and the components from
// operation_docs.h. A test checks that every served route is described.
#pragma once

#include <nlohmann/json.hpp>

namespace clearsky::api {

const nlohmann::ordered_json& openapi_document();

}  // namespace clearsky::api
