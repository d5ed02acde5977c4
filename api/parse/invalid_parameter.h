// The one error type of request parsing: a parameter (query parameter, JSON field or CLI option)
// whose value is missing, malformed, out of range, unknown or repeated. The HTTP layer answers
// it with status 400 and {"error": {"code": "invalid_parameter", "message": ..., "parameter":
// ...}}; the CLI prints it and exits with a non-zero status.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace clearsky::api {

class InvalidParameter : public std::invalid_argument {
 public:
  // what() is "<parameter>: <message>".
  InvalidParameter(std::string parameter, std::string message)
      : std::invalid_argument(parameter + ": " + message),
        parameter_(std::move(parameter)),
        message_(std::move(message)) {}

  const std::string& parameter() const noexcept { return parameter_; }
  // The explanation without the parameter name.
  const std::string& message() const noexcept { return message_; }

 private:
  std::string parameter_;
  std::string message_;
};

// A parameter's text in double quotes, for messages.
inline std::string quoted(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 2);
  out += '"';
  out += text;
  out += '"';
  return out;
}

}  // namespace clearsky::api
