// Client JSON through nlohmann's callback parser: the callback sees each value's depth before
// the value is added to the tree, and each top-level member's name.
#include "api/http/json_body.h"

#include "api/error/api_error.h"

namespace clearsky::api {

nlohmann::json parse_client_json(std::string_view text, const std::string& whole) {
  using Event = nlohmann::json::parse_event_t;
  // The top-level member being read: what an error names.
  std::string member;
  const auto at_fault = [&] { return member.empty() ? whole : member; };
  const nlohmann::json::parser_callback_t track = [&](int depth, Event event,
                                                      nlohmann::json& parsed) {
    // depth counts the arrays and objects around the value; a new one is one level deeper.
    if ((event == Event::object_start || event == Event::array_start) && depth >= kMaxJsonDepth) {
      throw ApiError::about(400, "invalid_body", at_fault(),
                            "nested deeper than " + std::to_string(kMaxJsonDepth) +
                                " levels of arrays and objects (the limit of a JSON body)");
    }
    if (depth == 1 && event == Event::key) member = parsed.get<std::string>();
    // The member's value is complete.
    if (depth == 1 &&
        (event == Event::value || event == Event::object_end || event == Event::array_end))
      member.clear();
    return true;
  };
  try {
    return nlohmann::json::parse(text, track);
  } catch (const nlohmann::json::out_of_range& e) {
    // 406: a number whose magnitude is beyond the largest double (about 1.8e308).
    throw ApiError::about(
        400, "invalid_parameter", at_fault(),
        "a number beyond the range of a double (about 1.8e308): " + std::string(e.what()));
  } catch (const nlohmann::json::exception& e) {
    throw ApiError::about(400, "invalid_body", at_fault(),
                          "not valid JSON: " + std::string(e.what()));
  }
}

}  // namespace clearsky::api
