// Constructors of the API's typed errors.
#include "api/error/api_error.h"

namespace clearsky::api {

ApiError invalid_parameter(const std::string& parameter, const std::string& message) {
  return ApiError(400, "invalid_parameter", parameter, parameter + ": " + message);
}

ApiError unknown_parameter(const std::string& parameter, const std::string& endpoint) {
  return ApiError(
      400, "unknown_parameter", parameter,
      parameter + ": not a parameter of " + endpoint + " (or not used by this request)");
}

ApiError missing_parameter(const std::string& parameter, const std::string& message) {
  return ApiError(400, "missing_parameter", parameter,
                  parameter + ": required" + (message.empty() ? "" : " (" + message + ")"));
}

ApiError conflicting_parameters(const std::string& parameter, const std::string& other) {
  return ApiError(400, "conflicting_parameters", parameter,
                  parameter + ": cannot be given together with " + other);
}

ApiError unknown_model(const std::string& id, const std::string& available) {
  return ApiError(
      404, "unknown_model", "model",
      "model: no model '" + id + "' (available: " + (available.empty() ? "none" : available) + ")");
}

ApiError too_large(const std::string& parameter, const std::string& message) {
  return ApiError(413, "too_large", parameter, parameter + ": " + message);
}

ApiError cannot_answer(const std::string& parameter, const std::string& model_id,
                       const std::string& reason) {
  return ApiError(422, "model_cannot_answer", parameter,
                  "model " + model_id + " cannot answer: " + reason);
}

ApiError not_ready(const std::string& model_id, const std::string& message, int retry_after_s) {
  return ApiError(503, "model_not_ready", "model", "model " + model_id + ": " + message,
                  retry_after_s);
}

ApiError from_invalid_argument(const std::invalid_argument& error) {
  const std::string message = error.what();
  const auto colon = message.find(':');
  std::string parameter;
  if (colon != std::string::npos && message.find(' ') > colon) parameter = message.substr(0, colon);
  return ApiError(400, "invalid_parameter", parameter, message);
}

}  // namespace clearsky::api
