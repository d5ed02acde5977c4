// The one error type of the HTTP API: an HTTP status, a stable machine-readable code, the
// request parameter at fault (empty when none) and a human-readable message. The server turns
// it into {"error": {"code", "message", "parameter"}} (docs/http-api.md).
// Handlers throw it at the edge (parsing, capability checks); models never see it.
#pragma once

#include <stdexcept>
#include <string>

namespace clearsky::api {

class ApiError : public std::runtime_error {
 public:
  ApiError(int status, std::string code, std::string parameter, const std::string& message,
           int retry_after_s = 0)
      : std::runtime_error(message),
        status_(status),
        code_(std::move(code)),
        parameter_(std::move(parameter)),
        retry_after_s_(retry_after_s) {}

  int status() const { return status_; }
  const std::string& code() const { return code_; }
  const std::string& parameter() const { return parameter_; }
  // Seconds for the Retry-After header of a 503; 0 when none applies.
  int retry_after_s() const { return retry_after_s_; }

 private:
  int status_;
  std::string code_;
  std::string parameter_;
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
// 422: the model's capabilities exclude the request; message says why.
ApiError cannot_answer(const std::string& parameter, const std::string& model_id,
                       const std::string& reason);
// 503: the tables the request needs are still being built.
ApiError not_ready(const std::string& model_id, const std::string& message, int retry_after_s);

// Converts a std::invalid_argument whose message starts with "name: " (the convention of
// models/ and AtmosphereParameters::validate) into a 400 naming that parameter.
ApiError from_invalid_argument(const std::invalid_argument& error);

}  // namespace clearsky::api
