// Bounded body reading (request_body.h).
#include "server/http/request_body.h"

#include <httplib.h>

#include "api/error/api_error.h"

namespace clearsky::server {

namespace {

// A request with neither Content-Length nor chunked transfer coding has no body (RFC 9112
// section 6.3): `curl -X POST .../pause` must not wait for one nor be refused.
bool has_body(const httplib::Request& req) {
  return req.has_header("Content-Length") || req.has_header("Transfer-Encoding");
}

}  // namespace

std::string read_limited_body(const httplib::Request& req, const httplib::ContentReader& content,
                              std::size_t limit_bytes, std::size_t drain_limit_bytes) {
  const auto too_large = [limit_bytes] {
    return api::too_large(
        "body", "the request body is above the limit of " + std::to_string(limit_bytes) + " bytes");
  };
  if (!has_body(req)) return {};
  // A declared length beyond the drain limit is refused by cpp-httplib itself (skipped).
  if (req.get_header_value<std::uint64_t>("Content-Length") > drain_limit_bytes) {
    content([](const char*, std::size_t) { return true; });
    throw too_large();
  }
  std::string body;
  std::size_t received = 0;
  const bool complete = content([&](const char* data, std::size_t size) {
    received += size;
    if (received <= limit_bytes) {
      body.append(data, size);
      return true;
    }
    body.clear();
    return received <= drain_limit_bytes;
  });
  if (received > limit_bytes) throw too_large();
  if (!complete)
    throw api::ApiError(400, "invalid_body", "body", "body: the request body could not be read");
  return body;
}

bool UploadBodyReader::read(const std::function<bool(std::string_view piece)>& receive) {
  if (!has_body(req_)) return complete_ = true;
  bool stopped = false;
  complete_ = content_([&](const char* data, std::size_t size) {
    if (receive(std::string_view(data, size))) return true;
    stopped = true;
    return false;
  });
  if (complete_) return true;
  if (stopped) return false;
  // cpp-httplib skips, without calling the receiver, a body above its payload limit.
  if (req_.get_header_value<std::uint64_t>("Content-Length") > limit_bytes_)
    throw api::too_large(
        "body", "the upload is above the limit of " + std::to_string(limit_bytes_) + " bytes");
  throw api::ApiError(400, "invalid_body", "body", "body: the upload could not be read");
}

}  // namespace clearsky::server
