// The quality parameter of the sky endpoints (docs/quality-levels.md):
//
// clang-format off
// | parameter | values                      | default                   | meaning                                                   |
// |-----------|-----------------------------|---------------------------|-----------------------------------------------------------|
// | quality   | draft, standard, reference  | serve --quality (standard) | the model's cost options (models/quality/<model>.csv)     |
// clang-format on
//
// The level sets the model's cost options; an option the request gives explicitly wins over the
// level's value (the answer then lists it in quality_overridden and states no error figures, which
// hold for the level's own setting only). Every answer states the quality asked, the quality whose
// tables answered, the option values used and the level's error figures.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "api/request/parameters.h"
#include "models/core/sky_model.h"
#include "models/quality/quality_levels.h"

namespace clearsky::api {

struct RequestQuality {
  std::string model_id;
  QualityLevel level = QualityLevel::standard;  // asked, or the server's default
  const QualitySetting* table_row = nullptr;    // the level's row of the model's table
  std::map<std::string, double> setting;        // every option the level lists, as used
  std::vector<std::string> overridden;          // the level's options the request set itself
};

// Reads `quality` (400 naming it for another value) and applies the level to config's options
// (after parse_sky_config: explicit options win).
RequestQuality parse_quality(Parameters& p, const ModelDescriptor& descriptor, ModelConfig& config,
                             QualityLevel default_level);

// The answer's members: quality, served_quality, quality_setting, quality_error (null when an
// option was overridden) and quality_overridden (when not empty).
void add_quality_members(nlohmann::json& body, const RequestQuality& quality, QualityLevel served);
// The headers Clearsky-Quality (asked), Clearsky-Served-Quality (whose tables answered) and
// Clearsky-Quality-Detail (quality_summary).
void add_quality_headers(std::vector<std::pair<std::string, std::string>>& headers,
                         const RequestQuality& quality, QualityLevel served);
// "draft; p95=0.012; max=0.05; setting=table_r_size=8,..." for an EXR or PNG header.
std::string quality_summary(const RequestQuality& quality, QualityLevel served);

}  // namespace clearsky::api
