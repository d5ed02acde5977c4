// The OpenAPI 3.0 description of HTTP API v1, served at GET /openapi.json. Written from the
// same parameter tables the handlers document in their headers (sky_request.h, place_time.h,
// skydome_render.h); a test checks that every served route is described.
#pragma once

#include <nlohmann/json.hpp>

namespace clearsky::api {

const nlohmann::json& openapi_document();

}  // namespace clearsky::api
