// Constructors of the API's typed errors, and the mapping of models-layer refusals.
#include "api/error/api_error.h"

#include <string_view>
#include <utility>

namespace clearsky::api {

namespace {

// SolarPositionInput field -> request parameter (api/request/place_time.h).
constexpr std::pair<std::string_view, std::string_view> kSolarFieldParameters[] = {
    {"unix_time_utc_s", "time"}, {"latitude_deg", "lat"},       {"longitude_deg", "lon"},
    {"elevation_m", "altitude"}, {"pressure_mbar", "pressure"}, {"temperature_c", "temperature"},
    {"delta_t_s", "delta_t"},    {"delta_ut1_s", "delta_ut1"},
};

// A JSON body's member named "" is the one parameter without a name (the HTTP layer drops a
// query parameter without one); an empty name would be written as no parameter (null), so it
// is named as the body (found by fuzz/api_routes_fuzz.cpp).
std::string named(const std::string& parameter) { return parameter.empty() ? "body" : parameter; }

}  // namespace

ApiError invalid_parameter(const std::string& parameter, const std::string& message) {
  return ApiError::about(400, "invalid_parameter", named(parameter),
                         parameter.empty() ? "a member named \"\": " + message : message);
}

ApiError unknown_parameter(const std::string& parameter, const std::string& endpoint) {
  if (parameter.empty())
    return ApiError::about(400, "unknown_parameter", named(parameter),
                           "a member named \"\" is not a parameter of " + endpoint);
  return ApiError::about(400, "unknown_parameter", parameter,
                         "not a parameter of " + endpoint + " (or not used by this request)");
}

ApiError insufficient_storage(const std::string& what) {
  return ApiError::about(507, "insufficient_storage", "disk",
                         "no space left on the server's disk while " + what);
}

ApiError missing_parameter(const std::string& parameter, const std::string& message) {
  return ApiError::about(400, "missing_parameter", parameter,
                         "required" + (message.empty() ? "" : " (" + message + ")"));
}

ApiError conflicting_parameters(const std::string& parameter, const std::string& other) {
  return ApiError::about(400, "conflicting_parameters", parameter,
                         "cannot be given together with " + other);
}

ApiError unknown_model(const std::string& id, const std::string& available) {
  return ApiError::about(
      404, "unknown_model", "model",
      "no model '" + id + "' (available: " + (available.empty() ? "none" : available) + ")");
}

ApiError too_large(const std::string& parameter, const std::string& message) {
  return ApiError::about(413, "too_large", parameter, message);
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

std::string request_parameter_of(const std::string& model_field) {
  for (const auto& [field, parameter] : kSolarFieldParameters) {
    if (field == model_field) return std::string(parameter);
  }
  return model_field;
}

ApiError from_invalid_input(const InvalidInput& error) {
  return invalid_parameter(request_parameter_of(error.field()), error.reason());
}

ApiError from_invalid_argument(const std::invalid_argument& error) {
  if (const auto* input = dynamic_cast<const InvalidInput*>(&error))
    return from_invalid_input(*input);
  return ApiError(400, "invalid_parameter", "model", error.what());
}

}  // namespace clearsky::api
