// The canonical form of a model configuration, the one the table store keys its entries by
// (server/tables/table_store.h) and builds from: an option given at its descriptor's default
// selects the same tables as the option left out, since a build reads the default for an absent
// option (ValidatedConfig::option, model_factory.h), so it is dropped. Without this, aerosols=0
// given to measured_aerosols and the option left out (the same shipped inversion) were two
// entries of identical tables (docs/model-contract.md "Factory and configuration").
#pragma once

#include "models/core/model_descriptor.h"
#include "models/core/sky_model.h"

namespace clearsky {

// config without the options the descriptor lists at their default value. Options the
// descriptor does not list are kept, for validate_config to refuse them by name.
ModelConfig canonical_config(const ModelDescriptor& descriptor, ModelConfig config);

}  // namespace clearsky
