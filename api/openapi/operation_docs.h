// The OpenAPI 3 Operation Object of each operationId of the route table
// (api/routes/route_table.h), and the document's components (schemas, security schemes) they
// refer to. openapi_document.h assembles them into /openapi.json.
#pragma once

#include <nlohmann/json.hpp>
#include <string_view>

namespace clearsky::api {
const nlohmann::ordered_json* operation_doc(std::string_view operation_id);
nlohmann::ordered_json openapi_components();
}  // namespace clearsky::api
