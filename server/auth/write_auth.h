// Bearer-token authorisation of the write endpoints (POST, DELETE, imports): the
// token is configured with --token or the CLEARSKY_TOKEN environment variable (the option
// wins); with no token configured, writes are disabled (403) and reads stay open. A request's
// "Authorization: Bearer TOKEN" is compared with the configured token in constant time
// (OpenSSL's CRYPTO_memcmp; the time depends on the configured token's length only, never on
// where the texts differ). The server checks it from the route table's needs-token column
// before it reads the request's body (server/http/http_server.cpp).
// Every write attempt, allowed or not, is logged on the spdlog logger "audit" (never the
// token itself). Thread-safety: immutable after construction.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace spdlog {
class logger;
}

namespace clearsky::server {

// The spdlog logger "audit" (created on first use) that records every write.
std::shared_ptr<spdlog::logger> audit_logger();

// True when a and b are equal, in time independent of their content.
bool constant_time_equal(std::string_view expected, std::string_view candidate);

class WriteAuthorizer {
 public:
  // An empty token counts as none.
  explicit WriteAuthorizer(std::optional<std::string> token);
  // The option's value if given, else the environment's (may be null), else none.
  static WriteAuthorizer from_option_or_environment(const std::string& option_value,
                                                    const char* environment_value);

  bool writes_enabled() const { return token_.has_value(); }
  // Whether the header carries the token (false when none is configured). Logs nothing.
  bool allows(std::string_view authorization_header) const;
  // Throws ApiError 403 (writes_disabled) when no token is configured, 401 (unauthorized)
  // when the header is absent, not "Bearer ...", or carries another token. Logs the attempt.
  void authorize(std::string_view method, std::string_view path,
                 std::string_view authorization_header, std::string_view remote) const;

 private:
  std::optional<std::string> token_;
};

}  // namespace clearsky::server
