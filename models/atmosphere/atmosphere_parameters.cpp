// Defaults, validation and canonical form of the atmosphere parameters, all from the one
// table of atmosphere_parameter_table.h.
#include "models/atmosphere/atmosphere_parameters.h"

#include <cmath>
#include <sstream>

#include "models/atmosphere/atmosphere_parameter_table.h"
#include "models/core/invalid_input.h"

namespace clearsky {

namespace {

// "must be in [0, 4]", "must be in (0, 100000]", or for an unbounded range "must be finite and
// > 0" (and "> earth_radius_m" for a parameter that must exceed another).
std::string range_reason(const AtmosphereParameterInfo& p) {
  std::ostringstream out;
  if (!p.above.empty()) {
    out << "must be finite and > " << p.above;
  } else if (std::isinf(p.max_value)) {
    out << "must be finite and " << (p.min_exclusive ? "> " : ">= ") << p.min_value;
  } else {
    out << "must be in " << (p.min_exclusive ? '(' : '[') << p.min_value << ", " << p.max_value
        << (p.max_exclusive ? ')' : ']');
  }
  return out.str();
}

}  // namespace

AtmosphereParameters::AtmosphereParameters() {
  for (const AtmosphereParameterInfo& p : kAtmosphereParameterTable) {
    if (p.has_numeric_default()) {
      p.set(*this, p.default_value);
    } else {
      this->*p.optional_member = std::nullopt;
    }
  }
}

void AtmosphereParameters::validate() const {
  for (const AtmosphereParameterInfo& p : kAtmosphereParameterTable) {
    if (p.optional_member != nullptr && !(this->*p.optional_member))
      continue;  // absent: the default spectrum
    const double value = p.value_in(*this);
    bool ok = p.in_range(value);
    if (!p.above.empty()) ok = ok && value > find_atmosphere_parameter(p.above)->value_in(*this);
    if (!ok) throw InvalidInput(std::string(p.name), range_reason(p));
  }
}

std::string AtmosphereParameters::canonical_string() const {
  std::ostringstream out;
  out.precision(17);
  bool first = true;
  for (const AtmosphereParameterInfo& p : kAtmosphereParameterTable) {
    if (!p.keys_models) continue;
    out << (first ? "" : ";") << p.canonical_key << '=';
    first = false;
    if (p.optional_member != nullptr && !(this->*p.optional_member)) {
      out << p.default_text;
    } else {
      out << p.value_in(*this);
    }
  }
  return out.str();
}

}  // namespace clearsky
