// The canonical form of a model configuration (canonical_config.h).
#include "models/core/canonical_config.h"

namespace clearsky {

ModelConfig canonical_config(const ModelDescriptor& descriptor, ModelConfig config) {
  std::erase_if(config.options, [&](const auto& option) {
    const ParameterSpec* spec = descriptor.find_parameter(option.first);
    return spec != nullptr && !spec->atmosphere && option.second == spec->default_value;
  });
  return config;
}

}  // namespace clearsky
