// Request bodies read through cpp-httplib's ContentReader, under the route's limit
// (api/routes/route_table.h BodyPolicy). cpp-httplib 0.11.4 (Debian 12) has one payload limit
// for the whole server, applied only to bodies with a Content-Length (it skips such a body and
// answers 413; chunked bodies are not limited), so the server sets it to the largest body any
// route takes (the upload) and:
// - JSON bodies are read here: kept up to limit_bytes, then read and discarded up to
//   drain_limit_bytes so that the client, still sending, gets the 413 (a server that stops
//   reading makes the client fail on its write); beyond drain_limit_bytes the connection is cut;
// - uploads are streamed to the handler through api::BodyReader (UploadBodyReader).
#pragma once

#include <cstddef>
#include <string>

#include "api/http/body_reader.h"

namespace httplib {
class ContentReader;
struct Request;
}  // namespace httplib

namespace clearsky::server {

// The body, or ApiError 413 (too_large, parameter "body") when it is above limit_bytes (by
// its Content-Length or by what arrived), 400 (invalid_body) when it could not be read.
std::string read_limited_body(const httplib::Request& req, const httplib::ContentReader& content,
                              std::size_t limit_bytes, std::size_t drain_limit_bytes);

// An upload as it arrives, for one request on the worker that serves it.
class UploadBodyReader final : public api::BodyReader {
 public:
  UploadBodyReader(const httplib::Request& req, const httplib::ContentReader& content,
                   std::size_t limit_bytes)
      : req_(req), content_(content), limit_bytes_(limit_bytes) {}
  bool read(const std::function<bool(std::string_view piece)>& receive) override;
  // Whether the whole body has been read.
  bool complete() const { return complete_; }

 private:
  const httplib::Request& req_;
  const httplib::ContentReader& content_;
  std::size_t limit_bytes_;
  bool complete_ = false;
};

}  // namespace clearsky::server
