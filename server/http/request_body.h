// Request bodies under the small payload limit on routes that read them through cpp-httplib's
// ContentReader. cpp-httplib 0.11.4 (Debian 12) has one payload limit for the whole server,
// applied only to bodies with a Content-Length (it skips such a body and answers 413; chunked
// bodies are not limited), so the server sets it to the upload limit and every other POST
// route reads its body here: kept up to limit_bytes, then read and discarded up to
// drain_limit_bytes so that the client, still sending, gets the 413 (a server that stops
// reading makes the client fail on its write); beyond drain_limit_bytes the connection is cut.
#pragma once

#include <cstddef>
#include <string>

namespace httplib {
class ContentReader;
struct Request;
}  // namespace httplib

namespace clearsky::server {

// The body, or ApiError 413 (too_large, parameter "body") when it is above limit_bytes (by
// its Content-Length or by what arrived), 400 (invalid_body) when it could not be read.
std::string read_limited_body(const httplib::Request& req, const httplib::ContentReader& content,
                              std::size_t limit_bytes, std::size_t drain_limit_bytes);

}  // namespace clearsky::server
