// Bearer tokens for writes (write_auth.h).
#include "server/auth/write_auth.h"

#include <openssl/crypto.h>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

#include "api/error/api_error.h"

namespace clearsky::server {
std::shared_ptr<spdlog::logger> audit_logger() {
  static std::shared_ptr<spdlog::logger> logger = [] {
    if (auto existing = spdlog::get("audit")) return existing;
    return spdlog::stdout_logger_mt("audit");
  }();
  return logger;
}

bool constant_time_equal(std::string_view expected, std::string_view candidate) {
  // CRYPTO_memcmp takes the same time whatever the bytes; a candidate of another length is
  // compared with expected itself, so that the time depends on expected's length only.
  const bool same_length = expected.size() == candidate.size();
  const std::string_view compared = same_length ? candidate : expected;
  const bool equal = CRYPTO_memcmp(expected.data(), compared.data(), expected.size()) == 0;
  return same_length && equal;
}

WriteAuthorizer::WriteAuthorizer(std::optional<std::string> token) {
  if (token && !token->empty()) token_ = std::move(token);
}

WriteAuthorizer WriteAuthorizer::from_option_or_environment(const std::string& option_value,
                                                            const char* environment_value) {
  if (!option_value.empty()) return WriteAuthorizer(option_value);
  if (environment_value != nullptr && *environment_value != '\0')
    return WriteAuthorizer(std::string(environment_value));
  return WriteAuthorizer(std::nullopt);
}

bool WriteAuthorizer::allows(std::string_view authorization_header) const {
  constexpr std::string_view kScheme = "Bearer ";
  if (!token_ || authorization_header.size() <= kScheme.size() ||
      authorization_header.substr(0, kScheme.size()) != kScheme)
    return false;
  return constant_time_equal(*token_, authorization_header.substr(kScheme.size()));
}

void WriteAuthorizer::authorize(std::string_view method, std::string_view path,
                                std::string_view authorization_header,
                                std::string_view remote) const {
  const auto refuse = [&](int status, const char* code, const std::string& message) {
    audit_logger()->warn("write refused: {} {} from {} ({})", method, path, remote, code);
    // The refusal names the request header the client must give (or cannot give: 403).
    throw api::ApiError(status, code, "Authorization", message);
  };
  if (!token_)
    refuse(403, "writes_disabled",
           "writes are disabled: the server has no token (--token or CLEARSKY_TOKEN)");
  constexpr std::string_view kScheme = "Bearer ";
  if (authorization_header.size() <= kScheme.size() ||
      authorization_header.substr(0, kScheme.size()) != kScheme)
    refuse(401, "unauthorized", "this request needs the header Authorization: Bearer TOKEN");
  if (!constant_time_equal(*token_, authorization_header.substr(kScheme.size())))
    refuse(401, "unauthorized", "the bearer token is not the server's");
  audit_logger()->info("write allowed: {} {} from {}", method, path, remote);
}

}  // namespace clearsky::server
