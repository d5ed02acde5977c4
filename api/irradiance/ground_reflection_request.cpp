// The ground-reflection parameters (ground_reflection_request.h).
#include "api/irradiance/ground_reflection_request.h"

#include "api/error/api_error.h"

namespace clearsky::api {

GroundReflection parse_ground_reflection(Parameters& p) {
  GroundReflection ground;
  ground.included = p.choice("ground_reflection", {"include", "exclude"}, "include") == "include";
  if (p.has("ground_albedo")) {
    if (!ground.included)
      throw conflicting_parameters("ground_albedo", "ground_reflection=exclude");
    ground.albedo = p.number("ground_albedo", 0.0, 1.0);
  }
  return ground;
}

nlohmann::json ground_reflection_json(const GroundReflection& ground) {
  if (!ground.included) return {{"model", "excluded"}};
  nlohmann::json out = {{"model", "isotropic"}};
  if (ground.albedo) {
    out["albedo"] = *ground.albedo;
    out["albedo_source"] = "ground_albedo";
  } else {
    out["albedo_source"] = "model";
  }
  return out;
}

}  // namespace clearsky::api
