// The one check of a model configuration against its descriptor.
#include "models/core/model_factory.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "models/atmosphere/atmosphere_parameter_table.h"
#include "models/core/invalid_input.h"

namespace clearsky {

namespace {

std::string range_text(const ParameterSpec& spec) {
  std::ostringstream out;
  out << "must be in [" << spec.min_value << ", " << spec.max_value << "]";
  return out.str();
}

}  // namespace

void validate_config(const ModelDescriptor& descriptor, const ModelConfig& config) {
  config.atmosphere.validate();
  // The atmosphere parameters the descriptor lists, within its (possibly narrower) range.
  for (const ParameterSpec& spec : descriptor.parameters) {
    if (!spec.atmosphere) continue;
    const AtmosphereParameterInfo* info = find_atmosphere_parameter(spec.name);
    if (info == nullptr) {
      throw std::logic_error("descriptor of " + descriptor.id +
                             " lists unknown atmosphere parameter " + spec.name);
    }
    if (info->optional_member != nullptr && !(config.atmosphere.*info->optional_member))
      continue;  // the default spectrum
    const double value = info->value_in(config.atmosphere);
    if (!(value >= spec.min_value && value <= spec.max_value))
      throw InvalidInput(spec.name, range_text(spec) + " for the " + descriptor.id + " model");
  }
  for (const auto& [name, value] : config.options) {
    const ParameterSpec* spec = descriptor.find_parameter(name);
    if (spec == nullptr) throw InvalidInput(name, "not a parameter of model " + descriptor.id);
    if (!(value >= spec->min_value && value <= spec->max_value))
      throw InvalidInput(name, range_text(*spec));
    if (spec->integer && value != std::floor(value)) throw InvalidInput(name, "must be an integer");
  }
}

double option_or_default(const ModelDescriptor& descriptor, const ModelConfig& config,
                         const std::string& name) {
  if (auto it = config.options.find(name); it != config.options.end()) return it->second;
  const ParameterSpec* spec = descriptor.find_parameter(name);
  if (spec == nullptr)
    throw std::logic_error("model " + descriptor.id + " has no parameter " + name);
  return spec->default_value;
}

double ValidatedConfig::option(std::string_view name) const {
  return option_or_default(*descriptor_, *config_, std::string(name));
}

ValidatedConfig validated_config(const ModelDescriptor& descriptor, const ModelConfig& config) {
  validate_config(descriptor, config);
  return ValidatedConfig(descriptor, config);
}

}  // namespace clearsky
