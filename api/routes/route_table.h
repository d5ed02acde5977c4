// The one route table of HTTP API v1: every (method, path pattern) the server answers, with
// its OpenAPI operationId (api/openapi/operation_docs.h documents it under that id), its
// transport-free handler, what it does with a request body, whether it needs the bearer token
// and how its answer may be cached. The server installs the table generically
// (server/http/http_server.cpp); /openapi.json is generated from it
// (api/openapi/openapi_document.h). docs/http-api.md explains each column and the checklist
// for adding an endpoint.
#pragma once

#include <span>
#include <string_view>

#include "api/http/api_types.h"
#include "api/http/cache_policy.h"

namespace clearsky::api {

using Handler = ApiResponse (*)(const ApiContext&, const ApiRequest&);

// What a route does with a request body.
enum class BodyPolicy {
  // None expected: one above the payload limit, or chunked, is refused unread (413); a small
  // one is read and ignored.
  none,
  // Read whole into ApiRequest::body, up to the payload limit (413 beyond).
  json,
  // Streamed through ApiRequest::body_reader up to the upload limit (a spool file on disk).
  upload,
};

struct Route {
  std::string_view method;
  std::string_view pattern;  // "/v1/jobs/{id}": {name} matches one non-empty path segment
  std::string_view operation_id;
  Handler handler;
  BodyPolicy body;
  bool needs_token;
  Caching caching;
};

// Every route, in the order of the OpenAPI document.
std::span<const Route> routes();

}  // namespace clearsky::api
