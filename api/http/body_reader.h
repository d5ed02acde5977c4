// A request body read as it arrives, for routes that stream it (an upload spooled to disk,
// api/routes/dataset_routes.cpp) instead of holding it in memory. The server implements it on
// its HTTP library (server/http/request_body.h); tests implement it over a string.
#pragma once

#include <functional>
#include <string_view>

namespace clearsky::api {

class BodyReader {
 public:
  virtual ~BodyReader() = default;
  // Calls receive with each piece of the body in order. Returns true when the body ended
  // (an absent body is empty), false when receive returned false (the rest is not read).
  // Throws ApiError 413 (too_large, parameter "body") above the route's limit, 400
  // (invalid_body) when the body could not be read.
  virtual bool read(const std::function<bool(std::string_view piece)>& receive) = 0;
};

}  // namespace clearsky::api
