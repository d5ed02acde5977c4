// Cross-origin requests from browsers (the Fetch standard's CORS protocol; docs/http-api.md
// "CORS"): answers to a request whose Origin is allowed carry Access-Control-Allow-Origin and
// expose the headers a client reads (ETag, Location, Retry-After, ...); OPTIONS on a known path
// answers 204 with Allow and, to an allowed origin's preflight, the path's methods, the request
// headers a client may send (Authorization, Content-Type) and how long the browser may keep the
// answer. No origin is allowed by default (`clearsky serve --cors-origin`); "*" allows any.
// Immutable after construction: thread-safe.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "api/http/api_types.h"

namespace clearsky::api {

class CorsPolicy {
 public:
  explicit CorsPolicy(std::vector<std::string> allowed_origins = {});

  bool allows(std::string_view origin) const;
  // Whether any origin is configured (without one, no answer carries CORS headers).
  bool enabled() const { return !origins_.empty(); }
  // Adds the CORS headers of an answer to a request from origin (none when absent or not
  // allowed; Vary: Origin whenever origins are configured, since the answer depends on it).
  // Adds nothing to an answer that has them already.
  void add_headers(std::optional<std::string_view> origin, ApiResponse& response) const;
  // The answer to OPTIONS on a known path whose methods give allow (route_match.h).
  ApiResponse options(const ApiRequest& request, const std::string& allow) const;

  // Seconds a browser may keep a preflight answer (Chromium keeps at most 7200).
  static constexpr int kMaxAgeS = 7200;

 private:
  std::vector<std::string> origins_;
  bool any_ = false;
};

}  // namespace clearsky::api
