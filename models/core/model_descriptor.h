// What a model is and what it can answer, published as is by the API (docs/model-contract.md):
// id, version, citation, spectral range, parameter table, capabilities. A request outside the
// capabilities is refused before anything is computed. Descriptors are written with designated
// initializers; their atmosphere entries come from atmosphere_parameter_spec()
// (models/atmosphere/atmosphere_parameter_table.h). Every member has a default initializer, so
// that a designated initializer may leave any out.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace clearsky {

struct ParameterSpec {
  std::string name{};  // as in requests, e.g. "turbidity"
  std::string unit{};  // "" for dimensionless
  std::string description{};
  double default_value = 0;
  double min_value = 0;  // inclusive
  double max_value = 0;  // inclusive
  bool integer = false;
  // True for the shared atmosphere parameters (alpha, beta, g, turbidity, albedo), which map to
  // AtmosphereParameters; false for options of this model (ModelConfig::options).
  bool atmosphere = false;
};

struct ModelCapabilities {
  double min_altitude_m = 0;  // observer altitudes answered
  double max_altitude_m = 0;  // 0: ground only; > top of atmosphere: space views
  bool view_from_space = false;
  bool view_below_horizon = false;   // views with zenith > 90 degrees
  bool aerial_perspective = false;   // radiance/transmittance to a point at a distance
  double max_sun_zenith_deg = 90.0;  // > 90: the sun below the horizon is answered
  // Beyond this sun zenith (degrees) the model's sky is dark: the sun is below the horizon of
  // the top of the model's atmosphere at every point the model integrates over, for every
  // altitude answered, so every radiance and irradiance the model computes is exactly zero.
  // SkyModel::prepare_sun then returns a dark state at once (no per-sun precomputation) and the
  // queries answer zeros without computing (docs/model-contract.md "Dark suns"). Unset: the
  // model declares none (e.g. views from space see the day side whatever the sun).
  std::optional<double> dark_beyond_sun_zenith_deg{};
  int scattering_orders = 1;  // -1: all orders (e.g. fitted to a full solver)
  bool per_sun_precomputation = false;
  bool sun_irradiance = true;
  bool sky_irradiance = true;
};

struct ModelDescriptor {
  std::string id{};       // "bruneton"
  std::string name{};     // "Bruneton 2008"
  std::string version{};  // bumped when numbers change; part of every cache key
  std::string citation{};
  std::string summary{};  // one paragraph: method and the 2016 study's choices
  std::vector<double> native_wavelengths_nm{};  // empty: any wavelength
  double min_wavelength_nm = 0;                 // answered spectral range
  double max_wavelength_nm = std::numeric_limits<double>::infinity();
  std::vector<ParameterSpec> parameters{};
  ModelCapabilities capabilities{};

  const ParameterSpec* find_parameter(const std::string& parameter_name) const {
    for (const auto& p : parameters)
      if (p.name == parameter_name) return &p;
    return nullptr;
  }
};

}  // namespace clearsky
