// Building parameters from requests, header lookup, and the JSON and error responses.
#include "api/http/api_types.h"

#include <algorithm>
#include <cmath>

#include "api/http/json_body.h"

namespace clearsky::api {

namespace {

bool same_name(std::string_view a, std::string_view b) {
  return std::ranges::equal(a, b, [](char x, char y) {
    const auto lower = [](char c) {
      return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
    };
    return lower(x) == lower(y);
  });
}

std::optional<std::string_view> find_header(const NameValues& headers, std::string_view name) {
  for (const auto& [key, value] : headers)
    if (same_name(key, name)) return std::string_view(value);
  return std::nullopt;
}

}  // namespace

const std::string& ApiRequest::path_parameter(std::string_view name) const {
  for (const auto& [key, value] : path_parameters)
    if (key == name) return value;
  throw std::logic_error("route " + route + " has no path parameter " + std::string(name));
}

std::optional<std::string_view> ApiRequest::header(std::string_view name) const {
  return find_header(headers, name);
}

std::string ApiRequest::endpoint() const { return method + " " + (route.empty() ? path : route); }

std::optional<std::string_view> ApiResponse::header(std::string_view name) const {
  return find_header(headers, name);
}

nlohmann::json request_body(const ApiRequest& request) { return parse_client_json(request.body); }

Parameters request_parameters(const ApiRequest& request,
                              std::initializer_list<std::string_view> structured) {
  Parameters p =
      request.method == "POST"
          ? Parameters::from_json_object(request.endpoint(), request_body(request), structured)
          : Parameters(request.endpoint());
  for (const auto& [name, value] : request.query) p.add(name, value);
  return p;
}

Parameters query_parameters(const ApiRequest& request) {
  Parameters p(request.endpoint());
  for (const auto& [name, value] : request.query) p.add(name, value);
  return p;
}

// Answers may carry stored text that came from clients (dataset names, capture labels read
// from archive entries): a byte that is not UTF-8 is written as U+FFFD rather than making the
// serializer throw (type_error 316), which would turn every later read of it into a 500.
ApiResponse json_response(const nlohmann::json& body, int status) {
  ApiResponse r;
  r.status = status;
  r.body = body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return r;
}

ApiResponse ordered_json_response(const nlohmann::ordered_json& body, int status) {
  ApiResponse r;
  r.status = status;
  r.body = body.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
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
