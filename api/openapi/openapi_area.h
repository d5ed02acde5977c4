// The pieces of the OpenAPI description (operation_docs.h), one function per area of the API,
// and the small builders they share. Every response body refers to a named schema of
// components.schemas; the errors to Error ({"error": {"code", "message", "parameter"}},
// api/error/api_error.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace clearsky::api::openapi {

using Json = nlohmann::ordered_json;

// One area: its Operation Objects by operationId and the components they add.
struct Area {
  Json operations = Json::object();
  Json components = Json::object();
};

// healthz, readyz, metrics, openapi, listModels (service_operations.cpp).
Area service_area();
// getSun, radiance, irradiance, rgb, skydome (sky_operations.cpp).
Area sky_area();
// datasets and imports (datasets_operations.cpp).
Area datasets_area();
// evaluations and jobs (evaluations_operations.cpp).
Area evaluations_area();
// atmosphere fits (fits_operations.cpp).
Area fits_area();
// users' AERONET inversions for measured_aerosols (aerosols_operations.cpp).
Area aerosols_area();
// Error, the shared responses, headers, parameters and the bearer scheme (openapi_common.cpp).
Json common_components();

// The query parameters every sky endpoint shares, as components.parameters: model, the sun
// (given or from place and time), altitude, and every parameter a registered model's
// descriptor lists, with the union of their ranges (sky_parameters.cpp).
Json sky_parameter_components();
// $refs to them, in the order of the document.
Json sky_parameter_refs();
// The same parameters as members of a POST body (name -> schema).
Json sky_body_properties();

// A JSON text of the content files, parsed keeping its key order (std::logic_error when it does
// not parse: a programming error caught by the tests).
Json parse(const char* text);
// {"$ref": "#/components/<kind>/<name>"}.
Json ref(const std::string& kind, const std::string& name);
// A response with a JSON body of components.schemas[schema], and an example when given.
Json json_response(const std::string& description, const std::string& schema,
                   const Json& example = nullptr);
// An error response: the Error schema, with the codes this status carries for the operation.
Json error_response(const std::string& description);
// The 503 of a busy or building server: Error with the Retry-After header.
Json retry_later_response(const std::string& description);
// Adds the responses every operation shares (413 for a body on a route that takes none, 500).
void add_common_errors(Json& operation, bool takes_body);
// Declares the 404 a query replica answers on a data route (code no_database, parameter role;
// docs/deploy.md "Roles").
void add_query_replica_answer(Json& operation);
// Gives every 4xx/5xx response of the operations that has only a description the Error body
// (and Retry-After on a 503) (datasets_operations.cpp).
void complete_errors(Json& operations);
// A GET whose success carries an ETag (a hash of the body) and Cache-Control, and answers 304
// to an If-None-Match naming the current tag (api/http/cache_policy.h).
void add_revalidation(Json& operation);
// Makes operation a write: bearer security, 401 and 403.
void make_write(Json& operation);

}  // namespace clearsky::api::openapi
