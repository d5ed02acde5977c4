// The sky endpoints' JSON (docs/http-api.md; the schemas Sun, Model, Radiance, Rgb, Irradiance
// and the batch requests of /openapi.json): batch bodies written, answers read into the typed
// results of sky_types.h.
//
// Thread-safety: pure functions.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "clearsky/client/sky_types.h"

namespace clearsky::client::detail {

// The body of POST /v1/radiance and POST /v1/rgb: the sky query's parameters as members, the
// views as [zenith, azimuth] pairs.
nlohmann::json radiance_batch_json(const RadianceBatchRequest& request);
nlohmann::json rgb_batch_json(const RgbBatchRequest& request);

SunPosition sun_position_of(const nlohmann::json& json);
std::vector<ModelInfo> models_of(const nlohmann::json& json);
RadianceResult radiance_of(const nlohmann::json& json);
IrradianceResult irradiance_of(const nlohmann::json& json);
IrradianceSeriesResult irradiance_series_of(const nlohmann::json& json);
SkyPatchesResult sky_patches_of(const nlohmann::json& json);
SkyMatrixResult sky_matrix_of(const nlohmann::json& json);
RgbResult rgb_of(const nlohmann::json& json);

}  // namespace clearsky::client::detail
