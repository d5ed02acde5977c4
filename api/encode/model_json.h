// JSON forms of model descriptors (served verbatim by GET /v1/models and `clearsky models`).
#pragma once

#include <nlohmann/json.hpp>

#include "models/core/model_descriptor.h"

namespace clearsky::api {

nlohmann::json descriptor_to_json(const ModelDescriptor& descriptor);

}  // namespace clearsky::api
