// The ground-reflection parameters of GET /v1/irradiance and GET /v1/irradiance/series
// (plane_irradiance.h):
//
// clang-format off
// | parameter         | unit | default | range             | meaning                                                  |
// |-------------------|------|---------|-------------------|----------------------------------------------------------|
// | ground_reflection | -    | include | include, exclude  | add the isotropic ground's reflection to tilted planes   |
// | ground_albedo     | -    | model   | [0, 1]            | its albedo; absent: the model's ground albedo spectrum   |
// clang-format on
//
// ground_albedo with ground_reflection=exclude is a 400 (conflicting parameters).
#pragma once

#include <nlohmann/json.hpp>

#include "api/irradiance/plane_irradiance.h"
#include "api/request/parameters.h"

namespace clearsky::api {

GroundReflection parse_ground_reflection(Parameters& p);

// {"model": "isotropic", "albedo_source": "model"}, {"model": "isotropic", "albedo": 0.2,
// "albedo_source": "ground_albedo"} or {"model": "excluded"}.
nlohmann::json ground_reflection_json(const GroundReflection& ground);

}  // namespace clearsky::api
