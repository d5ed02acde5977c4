// The one check a response header's text gets before it is written: HTTP/1.1 ends a header
// line at CR LF (RFC 9112 section 2.1), so a name or value holding CR or LF could end the header
// early and start another (response splitting). cpp-httplib's Response::set_header() drops such
// a header byte by byte; HttpServer::send() adds headers itself with this test instead.
#pragma once

#include <cstring>
#include <string_view>

namespace clearsky::server {

// Whether text holds CR or LF (two passes of glibc's vectorised memchr).
inline bool holds_line_break(std::string_view text) {
  return std::memchr(text.data(), '\r', text.size()) != nullptr ||
         std::memchr(text.data(), '\n', text.size()) != nullptr;
}

}  // namespace clearsky::server
