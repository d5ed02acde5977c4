// Cache headers of an answer (docs/http-api.md "Caching"; RFC 9111 and RFC 9110 section 13):
// Cache-Control from the route's policy, a strong ETag that is a hash of the body (xxHash
// XXH3, 128 bits), and 304 Not Modified when a GET's If-None-Match names the current tag.
// Error answers are never stored. A streamed body has no tag (it is not known before it is
// sent). An answer whose handler already set Cache-Control keeps it and gets no tag.
#pragma once

#include <string>
#include <string_view>

#include "api/http/api_types.h"

namespace clearsky::api {

// How a successful answer may be cached.
enum class Caching {
  // Depends on stored data, the clock or the process: Cache-Control: no-store.
  no_store,
  // Changes with the server's state: no-cache with an ETag (304 when unchanged).
  revalidate,
  // A function of the request for a given server build: public, max-age=86400 with an ETag.
  deterministic,
};

// The Cache-Control value of a policy.
std::string_view cache_control(Caching caching);
// "\"<32 hex digits>\"": XXH3-128 of the body.
std::string strong_etag(std::string_view body);
// Whether an If-None-Match value (a list of tags, weak or strong, or "*") names etag, by the
// weak comparison RFC 9110 section 13.1.2 prescribes.
bool if_none_match(std::string_view header_value, std::string_view etag);

// Sets the cache headers of response (the answer of a route with this policy to request) and
// turns it into 304 (no body) when the request's If-None-Match names its tag.
void apply_caching(Caching caching, const ApiRequest& request, ApiResponse& response);

}  // namespace clearsky::api
