// The radiance computation shared by /v1/radiance and /v1/rgb: the request's sun, viewpoint
// and views through one checked batch query, with the first sample the model cannot answer
// turned into an error that names its parameter and says why.
#pragma once

#include "api/request/sky_request.h"
#include "api/request/views.h"

namespace clearsky::api {

SpectralBatch checked_sky_radiance(const ModelProvider& provider,
                                   const std::shared_ptr<const SkyModel>& model, const SunSpec& sun,
                                   const Viewpoint& viewpoint, const ViewList& views);

nlohmann::json sun_json(const SunSpec& sun);

}  // namespace clearsky::api
