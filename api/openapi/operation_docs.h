// The OpenAPI description of each operation of HTTP API v1, by operationId, and the shared
// components its Operation Objects refer to (docs/openapi.md). The route table that generates
// the document's `paths` looks every row's Operation Object up here; the content lives in one
// file per area (openapi_area.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string_view>

namespace clearsky::api {

// The Operation Object of operation_id (built once, thread-safe); nullptr: undocumented.
const nlohmann::ordered_json* operation_doc(std::string_view operation_id);
// The document's `components`: schemas, parameters, responses, headers, securitySchemes.
nlohmann::ordered_json openapi_components();
// The document's top-level `tags`: each tag the operations use, with its description.
nlohmann::ordered_json openapi_tags();

}  // namespace clearsky::api
