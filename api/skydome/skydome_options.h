// The renderer options of GET /v1/skydome (docs/http-api.md "Skydome", docs/renderers.md): one
// table, read by the parser below and by the OpenAPI document (api/openapi/sky_operations.cpp),
// so that the accepted values, the defaults and the 400s cannot disagree.
//
// clang-format off
// | parameter   | values                   | default     | meaning                                                     |
// |-------------|--------------------------|-------------|-------------------------------------------------------------|
// | sun         | none, disc               | none        | disc: the limb-darkened solar disc (api/skydome/sun_disc.h) |
// | ground      | none, albedo, model      | see below   | below the horizon (api/skydome/skydome_ground.h)            |
// | units       | radiometric, photometric | radiometric | channels=rgb only: photometric = 683 lm/W x radiometric     |
// | compression | none, zip, piz           | none        | OpenEXR compression (api/skydome/exr_compression.h)         |
// clang-format on
//
// ground absent: model for a model that answers views below the horizon (its own ground), none
// for the others: the answer of requests that predate the option. ground=model for a model
// without views below the horizon is a 400 naming ground. Not thread-safe to parse (Parameters);
// the table is immutable.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "api/request/parameters.h"
#include "models/core/model_descriptor.h"

namespace clearsky::api {

enum class SunDisc { none, disc };
enum class Ground { none, albedo, model };
enum class PixelUnits { radiometric, photometric };
enum class ExrCompression { none, zip, piz };

// One row of the table above.
struct SkydomeOptionSpec {
  std::string_view name;
  std::vector<std::string_view> values;  // the first is the default, except for ground
  std::string_view default_text;         // as the OpenAPI document describes it
  std::string_view meaning;
  bool rgb_only = false;  // read (hence accepted) only with channels=rgb
};

std::span<const SkydomeOptionSpec> skydome_option_table();

struct SkydomeOptions {
  SunDisc sun = SunDisc::none;
  Ground ground = Ground::none;
  PixelUnits units = PixelUnits::radiometric;
  ExrCompression compression = ExrCompression::none;
};

// Reads every row of the table (units only when rgb): 400 naming the parameter for a value not
// in its row, and for ground=model with a model that has no ground.
SkydomeOptions parse_skydome_options(Parameters& p, bool rgb, const ModelDescriptor& descriptor);

}  // namespace clearsky::api
