// The broadband parameters of GET /v1/irradiance and GET /v1/irradiance/series
// (broadband_irradiance.h; docs/http-api.md "Broadband irradiance"), rows of the atmosphere
// table (models/atmosphere/atmosphere_parameter_table.h) that no model takes:
//
// clang-format off
// | parameter             | unit   | default | range   | meaning                                              |
// |-----------------------|--------|---------|---------|------------------------------------------------------|
// | precipitable_water_cm | cm     | 1.42    | [0, 10] | water vapour of the vertical column (ASTM G-173)     |
// | ozone_atm_cm          | atm-cm | 0.34    | [0, 1]  | ozone of the vertical column (ASTM G-173)            |
// clang-format on
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "api/request/parameters.h"
#include "models/atmosphere/atmosphere_parameters.h"

namespace clearsky::api {

// `atmosphere` with the request's absorbers (their defaults when absent).
AtmosphereParameters parse_broadband_absorbers(Parameters& p, AtmosphereParameters atmosphere);

// The answer's broadband member: the range, the absorbers and the method; null when the model
// cannot go broadband (`unavailable`, broadband_unavailable_reason).
nlohmann::json broadband_json(const std::optional<std::string>& unavailable,
                              const AtmosphereParameters& absorbers);

}  // namespace clearsky::api
