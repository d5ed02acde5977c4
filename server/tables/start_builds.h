// What the server builds at start (docs/quality-levels.md "Serving at once"): by default the
// draft of every model whose draft differs from its defaults, then every default (standard) but
// those built on first use (ModelFactory::standard_on_first_use: measured_aerosols), so that a
// table model answers from its draft tables within seconds while its standard tables build;
// with `serve --prebuild LIST` ("bruneton:standard,haber:draft") exactly the listed model
// levels, in that order.
#pragma once

#include <span>
#include <string>
#include <utility>
#include <vector>

#include "models/core/sky_model.h"
#include "models/quality/quality_levels.h"

namespace clearsky::server {

// The model's configuration at a quality level: the defaults with the level's options.
ModelConfig level_config(const ModelDescriptor& descriptor, QualityLevel level);

// std::invalid_argument (the CLI names --prebuild) for an item that is not model:level, a model not
// served or an unknown level.
std::vector<std::pair<const ModelFactory*, ModelConfig>> start_builds(
    std::span<const ModelFactory> served, const std::vector<std::string>& prebuild);

}  // namespace clearsky::server
