// CORS headers and preflight answers (cors.h).
#include "api/http/cors.h"

#include <algorithm>

namespace clearsky::api {

CorsPolicy::CorsPolicy(std::vector<std::string> allowed_origins)
    : origins_(std::move(allowed_origins)),
      any_(std::ranges::find(origins_, "*") != origins_.end()) {}

bool CorsPolicy::allows(std::string_view origin) const {
  return any_ || std::ranges::find(origins_, origin) != origins_.end();
}

void CorsPolicy::add_headers(std::optional<std::string_view> origin, ApiResponse& response) const {
  // Once per answer: a header given twice (Access-Control-Allow-Origin) makes browsers refuse it.
  if (origins_.empty() || response.header("Access-Control-Allow-Origin") ||
      response.header("Vary") == "Origin")
    return;
  if (!any_) response.headers.emplace_back("Vary", "Origin");
  if (!origin || !allows(*origin)) return;
  response.headers.emplace_back("Access-Control-Allow-Origin", any_ ? "*" : std::string(*origin));
  response.headers.emplace_back(
      "Access-Control-Expose-Headers",
      "ETag, Location, Retry-After, WWW-Authenticate, Allow, Content-Disposition, "
      "Clearsky-Quality, Clearsky-Served-Quality, Clearsky-Quality-Detail, Clearsky-Fit");
}

ApiResponse CorsPolicy::options(const ApiRequest& request, const std::string& allow) const {
  ApiResponse response;
  response.status = 204;
  response.content_type.clear();
  response.headers.emplace_back("Allow", allow);
  const auto origin = request.header("Origin");
  if (origin && allows(*origin) && request.header("Access-Control-Request-Method")) {
    response.headers.emplace_back("Access-Control-Allow-Methods", allow);
    response.headers.emplace_back("Access-Control-Allow-Headers", "Authorization, Content-Type");
    response.headers.emplace_back("Access-Control-Max-Age", std::to_string(kMaxAgeS));
  }
  add_headers(origin, response);
  return response;
}

}  // namespace clearsky::api
