// Building parameters from requests, and the JSON and error responses.
#include "api/http/api_types.h"

#include <cmath>

namespace clearsky::api {

nlohmann::json request_body(const ApiRequest& request) {
  try {
    return nlohmann::json::parse(request.body);
  } catch (const nlohmann::json::parse_error& e) {
    throw ApiError(400, "invalid_body", "",
                   std::string("the request body is not valid JSON: ") + e.what());
  }
}

Parameters request_parameters(const ApiRequest& request,
                              std::initializer_list<std::string_view> structured) {
  const std::string endpoint = request.method + " " + request.path;
  Parameters p = request.method == "POST"
                     ? Parameters::from_json_object(endpoint, request_body(request), structured)
                     : Parameters(endpoint);
  for (const auto& [name, value] : request.query) p.add(name, value);
  return p;
}

ApiResponse json_response(const nlohmann::json& body, int status) {
  ApiResponse r;
  r.status = status;
  r.body = body.dump();
  return r;
}

ApiResponse error_response(const ApiError& error) {
  nlohmann::json body = {
      {"error",
       {{"code", error.code()},
        {"message", error.what()},
        {"parameter", error.parameter().empty() ? nlohmann::json(nullptr)
                                                : nlohmann::json(error.parameter())}}}};
  ApiResponse r = json_response(body, error.status());
  if (error.retry_after_s() > 0)
    r.headers.emplace_back("Retry-After", std::to_string(error.retry_after_s()));
  return r;
}

nlohmann::json finite(double value) {
  if (!std::isfinite(value)) throw std::logic_error("a non-finite number was about to be sent");
  return value;
}

}  // namespace clearsky::api
