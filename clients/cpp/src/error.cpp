// clearsky::client::Error (error.h).
#include "clearsky/client/error.h"

#include <utility>

namespace clearsky::client {

namespace {

std::string describe(int status, const std::string& code, const std::string& message,
                     const std::string& parameter) {
  std::string text = "clearsky: ";
  if (status > 0) text += std::to_string(status) + " ";
  text += code;
  if (!parameter.empty()) text += " (" + parameter + ")";
  text += ": " + message;
  return text;
}

}  // namespace

Error::Error(int status, std::string code, const std::string& message, std::string parameter,
             std::optional<int> retry_after_s)
    : std::runtime_error(describe(status, code, message, parameter)),
      status_(status),
      code_(std::move(code)),
      message_(message),
      parameter_(std::move(parameter)),
      retry_after_s_(retry_after_s) {}

}  // namespace clearsky::client
