// The one error type of the models layer for an input out of its domain: a configuration value,
// a solar-position input, a model option. It names the field at fault (the name the model's
// descriptor or the input struct uses, such as "alpha", "table_mu_size" or "latitude_deg") and
// says why, so that the layers above map it to their own parameter names by the field, never by
// parsing message text. what() stays "<field>: <reason>" for logs and for callers that only
// need a message (it is a std::invalid_argument).
#pragma once

#include <stdexcept>
#include <string>

namespace clearsky {

class InvalidInput : public std::invalid_argument {
 public:
  InvalidInput(std::string field, std::string reason)
      : std::invalid_argument(field + ": " + reason),
        field_(std::move(field)),
        reason_(std::move(reason)) {}

  // The input's name as the models layer spells it.
  const std::string& field() const noexcept { return field_; }
  // Why the value is refused, without the field's name ("must be in [0, 4]").
  const std::string& reason() const noexcept { return reason_; }

 private:
  std::string field_;
  std::string reason_;
};

}  // namespace clearsky
