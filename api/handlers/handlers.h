// The JSON/CSV endpoints of HTTP API v1 (docs/http-api.md), one file each. Each parses and
// validates its request completely before computing (errors are ApiError), calls the model
// through the ModelProvider, and encodes the answer. Thread-safe: they share only the provider.
#pragma once

#include "api/http/api_types.h"

namespace clearsky::api {

ApiResponse get_models(const ApiContext& context, const ApiRequest& request);
ApiResponse get_sun(const ApiContext& context, const ApiRequest& request);
// GET (one view) and POST (a batch in the body).
ApiResponse radiance(const ApiContext& context, const ApiRequest& request);
ApiResponse irradiance(const ApiContext& context, const ApiRequest& request);
// GET: irradiance from start to end every step on several planes, streamed
// (irradiance_series_handler.cpp).
ApiResponse irradiance_series(const ApiContext& context, const ApiRequest& request);
// GET (one view) and POST (a batch in the body).
ApiResponse rgb(const ApiContext& context, const ApiRequest& request);
// GET: a sky vector over Tregenza or Reinhart patches (skypatches_handler.cpp).
ApiResponse skypatches(const ApiContext& context, const ApiRequest& request);

}  // namespace clearsky::api
