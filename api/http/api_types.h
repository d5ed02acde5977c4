// The transport-free request and response of the API handlers: what the server's HTTP layer
// hands in (method, path, query pairs, body) and what it sends back. Value types.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "api/error/api_error.h"
#include "api/request/sky_request.h"
#include "api/service/model_provider.h"

namespace clearsky::api {

struct ApiRequest {
  std::string method = "GET";
  std::string path;
  std::vector<std::pair<std::string, std::string>> query;
  std::string body;
};

struct ApiResponse {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
  std::vector<std::pair<std::string, std::string>> headers;
  std::string model_id;  // the model that answered, for metrics; empty when none
};

// What handlers need besides the request.
struct ApiContext {
  const ModelProvider& models;
  Limits limits;
};

// The request's parameters: the query for GET; for POST, the JSON body's scalar members (the
// members named in structured are left to the handler) plus the query.
Parameters request_parameters(const ApiRequest& request,
                              std::initializer_list<std::string_view> structured = {});
// The parsed JSON body of a POST (400 when it does not parse).
nlohmann::json request_body(const ApiRequest& request);

ApiResponse json_response(const nlohmann::json& body, int status = 200);
// {"error": {"code", "message", "parameter"}} with the error's status and Retry-After.
ApiResponse error_response(const ApiError& error);
// A JSON number, or std::logic_error for NaN or infinity (NaN never reaches JSON: nlohmann
// would write null without a word).
nlohmann::json finite(double value);

}  // namespace clearsky::api
