// The altitude at which a model answers for a broadband irradiance sample (docs/data-api.md
// "Evaluations of broadband irradiance"): the site's elevation above sea level, taken as the
// observer's altitude above the ground sphere of the model's atmosphere (sea level), as
// GET /v1/irradiance takes its altitude= parameter. A model whose descriptor does not answer
// that altitude (ModelCapabilities::min_altitude_m, max_altitude_m: Haber answers at the
// ground only, none answers below sea level) answers at its ground instead, and the run says
// so (model_altitude_note): the difference is not clamped away in silence.
// Thread-safe (pure functions).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "models/core/model_descriptor.h"

namespace clearsky::api {

struct ModelAltitude {
  double altitude_m = 0;
  bool at_site_elevation = true;  // false: the model cannot answer the site's elevation
};

ModelAltitude model_altitude_for_site(const ModelDescriptor& descriptor, double site_elevation_m);

// One line for the run's processing steps: the altitude the model answered at, and, where it is
// not the site's elevation, why. site_elevations_m: the samples' (one per site in practice).
std::string model_altitude_note(const ModelDescriptor& descriptor,
                                const std::vector<double>& site_elevations_m);

}  // namespace clearsky::api
