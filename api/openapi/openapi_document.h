// The OpenAPI 3.0 description of HTTP API v1, served at GET /openapi.json: generated from the
// route table (api/routes/route_table.h), each route's path and method holding the Operation
// Object its operationId has in api/openapi/operation_docs.h, with the components, the
// servers and the info. std::logic_error when a route has no operation doc (a test checks
// both ways).
#pragma once

#include <nlohmann/json.hpp>

namespace clearsky::api {

const nlohmann::ordered_json& openapi_document();

}  // namespace clearsky::api
