// The list of registered models, in the paper's order.
#include "models/registry.h"

#include <vector>

#include "models/bruneton/bruneton.h"
#include "models/elek/elek.h"
#include "models/haber/haber.h"
#include "models/hosek/hosek.h"
#include "models/measured_aerosols/measured_aerosols.h"
#include "models/nishita93/nishita93.h"
#include "models/nishita96/nishita96.h"
#include "models/oneal/oneal.h"
#include "models/preetham/preetham.h"

namespace clearsky {

std::span<const ModelFactory> registered_models() {
  static const std::vector<ModelFactory> factories = {
      // The paper's order: Nishita93, Nishita96, Preetham, O'Neal, Haber, Bruneton, Elek, Hosek;
      // then the models beyond the paper.
      nishita93_factory(), nishita96_factory(),    preetham_factory(),
      oneal_factory(),     haber::model_factory(), bruneton_factory(),
      elek_factory(),      hosek_factory(),        measured_aerosols_factory(),
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
