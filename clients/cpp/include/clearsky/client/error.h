// clearsky::client::Error: the one exception of the client library. Every refusal of the server
// ({"error": {"code", "message", "parameter"}}, docs/http-api.md "Errors") becomes an Error with
// the HTTP status, the API's stable code, its message and the parameter it names; so does a
// failure to reach the server (status 0, code "connection") and an answer the library cannot
// read (code "invalid_answer").
//
// Thread-safety: immutable after construction; may be read from any thread.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

namespace clearsky::client {

class Error : public std::runtime_error {
 public:
  // status: the HTTP status (0 when no answer came); code: the API's error code; parameter:
  // the query parameter, body member (views[3]), path segment or header at fault, empty when
  // the error names none; retry_after_s: the answer's Retry-After, when it had one.
  Error(int status, std::string code, const std::string& message, std::string parameter = {},
        std::optional<int> retry_after_s = std::nullopt);

  int status() const noexcept { return status_; }
  const std::string& code() const noexcept { return code_; }
  // The server's message (what() prefixes it with the status and code).
  const std::string& message() const noexcept { return message_; }
  const std::string& parameter() const noexcept { return parameter_; }
  const std::optional<int>& retry_after_s() const noexcept { return retry_after_s_; }

 private:
  int status_;
  std::string code_;
  std::string message_;
  std::string parameter_;
  std::optional<int> retry_after_s_;
};

}  // namespace clearsky::client
