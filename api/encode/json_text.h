// JSON text written straight into a string, laid out as nlohmann::json's dump() writes the same
// values: for hot answers (GET /v1/radiance) whose DOM cost more than their computation
// (callgrind: building, dumping and freeing the DOM was over half of the handler). A number's
// digits are the shortest decimal that reads back as the same double, and of those the
// closest (Dragonbox, from {fmt}); dump()'s Grisu2 gives the same digits for all but about one
// in 1,500 values between 1e-12 and 1e4, and one more or a different last digit for those. The digits are laid out by
// dump()'s rules (docs/conventions.md "Numbers"): 45.0, 0.012345, 1e-07, 1.5e+16, -0.0.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace clearsky::api {

// A double's shortest round-trip digits in dump()'s layout; null when not finite.
void append_json_number(std::string& out, double value);
// A number the answer must never carry as null (api/http/api_types.h finite()): throws
// std::logic_error for NaN or infinity, as finite() does.
void append_finite_json_number(std::string& out, double value);
// [v0,v1,...] of append_json_number.
void append_json_number_array(std::string& out, const std::vector<double>& values);
// A string with dump()'s escaping (plain ASCII is copied; anything else is left to nlohmann).
void append_json_string(std::string& out, std::string_view text);

// An object whose members' values are JSON text already: written in nlohmann::json's member
// order (std::map: keys sorted bytewise), as {"key":value,...}.
class JsonObjectText {
 public:
  void add(std::string_view key, std::string_view value_text) {
    members_.emplace_back(key, value_text);
  }
  void append_to(std::string& out);

 private:
  std::vector<std::pair<std::string_view, std::string_view>> members_;
};

}  // namespace clearsky::api
