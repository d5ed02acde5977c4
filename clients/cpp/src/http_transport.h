// The HTTP exchange of the client library: one cpp-httplib connection per request, the bearer
// token, the timeouts, the retries of a 503/429 with Retry-After (client.h), and every error
// answer turned into clearsky::client::Error from its JSON body (docs/http-api.md "Errors").
//
// Thread-safety: const methods may be called from several threads at once.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

#include "clearsky/client/client.h"

namespace clearsky::client {

// A successful answer (status below 400).
struct HttpAnswer {
  int status = 0;
  std::string body;
  std::string location;      // Location
  std::string link;          // Link (docs/data-api.md "Pagination")
  std::string content_type;  // Content-Type
};

class HttpTransport {
 public:
  explicit HttpTransport(ClientOptions options);

  HttpAnswer get(const std::string& target) const;
  HttpAnswer post_json(const std::string& target, const std::string& json) const;
  // A POST without a body (pause, resume).
  HttpAnswer post_empty(const std::string& target) const;
  HttpAnswer remove(const std::string& target) const;
  // The file streamed as the body, 64 KiB at a time.
  HttpAnswer post_file(const std::string& target, const std::filesystem::path& file,
                       const UploadProgress& progress) const;
  // The body written to `out` as it arrives; an error answer's body is kept apart (it is
  // small) and becomes the Error.
  SkydomeDownload get_to_stream(const std::string& target, std::ostream& out) const;

  const ClientOptions& options() const { return options_; }

 private:
  ClientOptions options_;
};

// The next page's cursor in a Link header (`<...&cursor=X>; rel="next"`), if any.
std::optional<std::string> next_cursor(const std::string& link);

}  // namespace clearsky::client
