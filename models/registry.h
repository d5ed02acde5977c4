// The registered models, in the paper's order. Each model folder contributes one
// ModelFactory (see its <model>.h); this list is the only place that names them all.
#pragma once

#include <span>
#include <string_view>

#include "models/core/sky_model.h"

namespace clearsky {

std::span<const ModelFactory> registered_models();
// The factory of a model id, or nullptr.
const ModelFactory* find_model(std::string_view id);

}  // namespace clearsky
