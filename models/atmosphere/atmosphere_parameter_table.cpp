// Look-ups in the atmosphere parameter table and the descriptor entries made from it.
#include "models/atmosphere/atmosphere_parameter_table.h"

#include <stdexcept>
#include <string>

namespace clearsky {

const AtmosphereParameterInfo* find_atmosphere_parameter(std::string_view name) {
  for (const AtmosphereParameterInfo& p : kAtmosphereParameterTable)
    if (p.name == name) return &p;
  return nullptr;
}

bool set_atmosphere_parameter(AtmosphereParameters& atmosphere, std::string_view name,
                              double value) {
  const AtmosphereParameterInfo* p = find_atmosphere_parameter(name);
  if (p == nullptr) return false;
  p->set(atmosphere, value);
  return true;
}

ParameterSpec atmosphere_parameter_spec(std::string_view name) {
  const AtmosphereParameterInfo* p = find_atmosphere_parameter(name);
  if (p == nullptr) throw std::logic_error("no atmosphere parameter is named " + std::string(name));
  return atmosphere_parameter_spec(name, p->min_value, p->max_value);
}

ParameterSpec atmosphere_parameter_spec(std::string_view name, double min_value, double max_value) {
  const AtmosphereParameterInfo* p = find_atmosphere_parameter(name);
  if (p == nullptr) throw std::logic_error("no atmosphere parameter is named " + std::string(name));
  // A descriptor range is inclusive: an exclusive table bound cannot be published as is.
  if (!(p->in_range(min_value) && p->in_range(max_value) && min_value <= max_value))
    throw std::logic_error("descriptor range of " + std::string(name) +
                           " is not within the atmosphere parameter table's");
  return ParameterSpec{.name = std::string(p->name),
                       .unit = std::string(p->unit),
                       .description = std::string(p->description),
                       .default_value = p->default_value,
                       .min_value = min_value,
                       .max_value = max_value,
                       .integer = false,
                       .atmosphere = true};
}

}  // namespace clearsky
