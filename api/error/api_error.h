// The one error type of the API and the CLI: an HTTP status, a stable machine-readable code, the
// request parameter at fault (empty when none) and a human-readable message. The server turns
// it into {"error": {"code", "message", "parameter"}} (docs/http-api.md); the CLI prints the
// message under the option's name (docs/request-parsing.md). Handlers throw it at the edge
// (parsing, capability checks); models never see it: they throw clearsky::InvalidInput, which
// from_invalid_input turns into an ApiError naming the request parameter. Messages and
// parameter names often quote the client's text: both are kept valid UTF-8 and bounded here
// (api/error/utf8_text.h), so that every error can be written as JSON.
#pragma once

#include <stdexcept>
#include <string>

#include "api/error/utf8_text.h"
#include "models/core/invalid_input.h"

namespace clearsky::api {

class ApiError : public std::runtime_error {
 public:
  // message is the whole text (what()); reason() is then the same text.
  ApiError(int status, std::string code, const std::string& parameter, const std::string& message,
           int retry_after_s = 0)
      : std::runtime_error(quoted_client_text(message, kMaxMessageBytes)),
        status_(status),
        code_(std::move(code)),
        parameter_(quoted_client_text(parameter, kMaxParameterBytes)),
        reason_(what()),
        retry_after_s_(retry_after_s) {}

  // An error about a parameter: what() is "<parameter>: <reason>".
  static ApiError about(int status, std::string code, const std::string& parameter,
                        const std::string& reason) {
    ApiError error(status, std::move(code), parameter,
                   quoted_client_text(parameter, kMaxParameterBytes) + ": " + reason);
    error.reason_ = quoted_client_text(reason, kMaxMessageBytes);
    return error;
  }

  // Bounds of the client text an error quotes (a 8 MiB body member named in an error is not
  // sent back whole).
  static constexpr std::size_t kMaxMessageBytes = 1024;
  static constexpr std::size_t kMaxParameterBytes = 256;

  int status() const { return status_; }
  const std::string& code() const { return code_; }
  const std::string& parameter() const { return parameter_; }
  // Why, without the parameter's name (for the CLI, which names the option instead).
  const std::string& reason() const { return reason_; }
  // Seconds for the Retry-After header of a 503; 0 when none applies.
  int retry_after_s() const { return retry_after_s_; }

 private:
  int status_;
  std::string code_;
  std::string parameter_;
  std::string reason_;
  int retry_after_s_;
};

// 400: a value that does not parse or is out of its range (NaN included).
ApiError invalid_parameter(const std::string& parameter, const std::string& message);
// 400: a parameter the endpoint does not know or does not use.
ApiError unknown_parameter(const std::string& parameter, const std::string& endpoint);
// 400: a required parameter is absent.
ApiError missing_parameter(const std::string& parameter, const std::string& message = "");
// 400: two parameters that cannot be given together; names the second.
ApiError conflicting_parameters(const std::string& parameter, const std::string& other);
// 404: no registered model has this id.
ApiError unknown_model(const std::string& id, const std::string& available);
// 413: a request above a configured limit (image size, batch size, wavelength count).
ApiError too_large(const std::string& parameter, const std::string& message);
// 507 insufficient_storage naming "disk" (RFC 4918 section 11.5): the server's disk is full
// (ENOSPC, or EFBIG under a file size limit, while spooling an upload; SQLITE_FULL while
// writing the database); what says what was being written.
ApiError insufficient_storage(const std::string& what);
// 422: the model's capabilities exclude the request; message says why.
ApiError cannot_answer(const std::string& parameter, const std::string& model_id,
                       const std::string& reason);
// 503: the tables the request needs are still being built.
ApiError not_ready(const std::string& model_id, const std::string& message, int retry_after_s);

// The request parameter a models-layer input field comes from: the fields of SolarPositionInput
// by their table (latitude_deg -> lat, unix_time_utc_s -> time, ...); atmosphere parameters and
// model options already carry their request names.
std::string request_parameter_of(const std::string& model_field);
// 400 naming request_parameter_of(error.field()), with the model's reason.
ApiError from_invalid_input(const InvalidInput& error);
// A models-layer refusal: an InvalidInput as from_invalid_input; any other std::invalid_argument
// (a model check that does not name its field yet) is a 400 naming "model", with its message
// as it is. The message text is never parsed.
ApiError from_invalid_argument(const std::invalid_argument& error);

}  // namespace clearsky::api
