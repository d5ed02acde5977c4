// Reading the members of the server's JSON answers (json_fields.h).
#include "json_fields.h"

namespace clearsky::client::detail {

nlohmann::json parse_answer(const std::string& body, int status) {
  nlohmann::json json = nlohmann::json::parse(body, nullptr, false);
  if (json.is_discarded())
    throw Error(status, "invalid_answer", "the answer is not JSON: " + body.substr(0, 200));
  return json;
}

nlohmann::json parameters_json(const Parameters& parameters) {
  nlohmann::json object = nlohmann::json::object();
  for (const auto& [name, value] : parameters) {
    if (const double* number = std::get_if<double>(&value))
      object[name] = *number;
    else
      object[name] = std::get<std::string>(value);
  }
  return object;
}

Parameters parameters_of(const nlohmann::json& object) {
  Parameters parameters;
  if (!object.is_object()) return parameters;
  for (const auto& [name, value] : object.items()) {
    if (value.is_number())
      parameters[name] = value.get<double>();
    else if (value.is_string())
      parameters[name] = value.get<std::string>();
    else
      throw Error(0, "invalid_answer", "parameter " + name + " is neither a number nor a text");
  }
  return parameters;
}

}  // namespace clearsky::client::detail
