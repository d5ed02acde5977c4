// The list of registered models. Models are added here as their issues land.
#include "models/registry.h"

#include <vector>

#include "models/haber/haber.h"
#include "models/nishita93/nishita93.h"
#include "models/nishita96/nishita96.h"
#include "models/oneal/oneal.h"

namespace clearsky {

std::span<const ModelFactory> registered_models() {
  static const std::vector<ModelFactory> factories = {
      nishita93_factory(),
      nishita96_factory(),
      oneal_factory(),
      haber::kFactory,
  };
  return factories;
}

const ModelFactory* find_model(std::string_view id) {
  for (const ModelFactory& factory : registered_models()) {
    if (factory.descriptor->id == id) return &factory;
  }
  return nullptr;
}

}  // namespace clearsky
