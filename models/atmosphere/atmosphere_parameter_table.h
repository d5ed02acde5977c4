// The shared atmosphere parameters, declared once: for each, its name in requests (which is
// also the field an InvalidInput names), its key in canonical strings, unit, default, valid
// range, description and the AtmosphereParameters member it sets. Everything else derives from
// this table: the defaults of AtmosphereParameters, validate(), canonical_string() (cache keys:
// the order and keys of the table are those of the canonical string), every model descriptor's
// atmosphere ParameterSpec entries (atmosphere_parameter_spec) and request parsing
// (set_atmosphere_parameter). The comment table in atmosphere_parameters.h is checked against
// it by tests/models/atmosphere/atmosphere_parameter_table_test.cpp.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <span>
#include <string_view>

#include "models/atmosphere/atmosphere_parameters.h"
#include "models/core/model_descriptor.h"

namespace clearsky {

struct AtmosphereParameterInfo {
  std::string_view name{};           // in requests and InvalidInput::field(), e.g. "alpha"
  std::string_view canonical_key{};  // in canonical_string(), e.g. "alpha" or "R"
  std::string_view unit{};           // "" for dimensionless
  std::string_view description{};
  // The default; for the ground albedo (whose default is the grass spectrum, not a number)
  // NaN, with default_text "grass".
  double default_value = 0;
  std::string_view default_text{};
  double min_value = 0;
  double max_value = 0;
  bool min_exclusive = false;
  bool max_exclusive = false;
  // When not empty, the value must also exceed this other parameter's (the top of the
  // atmosphere above the ground).
  std::string_view above{};
  // False for the molecular absorbers, which the broadband irradiance applies after the model
  // (api/irradiance/broadband_irradiance.h): no model's sky depends on them, so they are left
  // out of canonical_string() and do not key any model's tables or caches.
  bool keys_models = true;
  // Exactly one of the two is set: the member, or the optional member whose absence means
  // default_text (the ground albedo).
  double AtmosphereParameters::*member = nullptr;
  std::optional<double> AtmosphereParameters::*optional_member = nullptr;

  bool has_numeric_default() const { return default_text.empty(); }
  // The value in p, or NaN for an absent optional value.
  double value_in(const AtmosphereParameters& p) const {
    if (member != nullptr) return p.*member;
    const std::optional<double>& v = p.*optional_member;
    return v ? *v : std::numeric_limits<double>::quiet_NaN();
  }
  void set(AtmosphereParameters& p, double value) const {
    if (member != nullptr) {
      p.*member = value;
    } else {
      p.*optional_member = value;
    }
  }
  bool in_range(double value) const {
    const bool above_min = min_exclusive ? value > min_value : value >= min_value;
    const bool below_max = max_exclusive ? value < max_value : value <= max_value;
    return above_min && below_max;
  }
};

namespace atmosphere_table_detail {
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline constexpr double kNoNumber = std::numeric_limits<double>::quiet_NaN();
}  // namespace atmosphere_table_detail

// In the order of canonical_string(). The aerosol ranges are those the descriptors have always
// published: |g| <= 0.999 keeps the Cornette-Shanks phase function's forward peak finite on the
// models' angular grids.
inline constexpr std::array<AtmosphereParameterInfo, 13> kAtmosphereParameterTable = {{
    {.name = "earth_radius_m",
     .canonical_key = "R",
     .unit = "m",
     .description = "radius of the ground sphere",
     .default_value = 6360e3,
     .min_value = 0.0,
     .max_value = atmosphere_table_detail::kInfinity,
     .min_exclusive = true,
     .max_exclusive = true,
     .member = &AtmosphereParameters::earth_radius_m},
    {.name = "top_radius_m",
     .canonical_key = "top",
     .unit = "m",
     .description = "radius of the top of the atmosphere",
     .default_value = 6420e3,
     .min_value = 0.0,
     .max_value = atmosphere_table_detail::kInfinity,
     .min_exclusive = true,
     .max_exclusive = true,
     .above = "earth_radius_m",
     .member = &AtmosphereParameters::top_radius_m},
    {.name = "rayleigh_scale_height_m",
     .canonical_key = "HR",
     .unit = "m",
     .description = "scale height of the air density exp(-h/H)",
     .default_value = 8000.0,
     .min_value = 0.0,
     .max_value = 1e5,
     .min_exclusive = true,
     .member = &AtmosphereParameters::rayleigh_scale_height_m},
    {.name = "mie_scale_height_m",
     .canonical_key = "HM",
     .unit = "m",
     .description = "scale height of the aerosol density exp(-h/H)",
     .default_value = 1200.0,
     .min_value = 0.0,
     .max_value = 1e5,
     .min_exclusive = true,
     .member = &AtmosphereParameters::mie_scale_height_m},
    {.name = "rayleigh_temperature_celsius",
     .canonical_key = "T",
     .unit = "C",
     .description = "air temperature of the Rayleigh coefficients (Penndorf's 0 C table x "
                    "273.16/(273.16+T))",
     .default_value = 15.0,
     .min_value = -100.0,
     .max_value = 100.0,
     .member = &AtmosphereParameters::rayleigh_temperature_celsius},
    {.name = "alpha",
     .canonical_key = "alpha",
     .unit = "",
     .description = "Angstrom exponent of the aerosol optical depth beta lambda_um^-alpha",
     .default_value = 0.8,
     .min_value = 0.0,
     .max_value = 4.0,
     .member = &AtmosphereParameters::angstrom_alpha},
    {.name = "beta",
     .canonical_key = "beta",
     .unit = "",
     .description = "Angstrom turbidity: aerosol optical depth at 1 um",
     .default_value = 0.04,
     .min_value = 0.0,
     .max_value = 2.0,
     .member = &AtmosphereParameters::angstrom_beta},
    {.name = "mie_single_scattering_albedo",
     .canonical_key = "ssa",
     .unit = "",
     .description = "aerosol single-scattering albedo (scattering / extinction)",
     .default_value = 0.8,
     .min_value = 0.0,
     .max_value = 1.0,
     .member = &AtmosphereParameters::mie_single_scattering_albedo},
    {.name = "g",
     .canonical_key = "g",
     .unit = "",
     .description = "asymmetry of the Cornette-Shanks aerosol phase function",
     .default_value = 0.7,
     .min_value = -0.999,
     .max_value = 0.999,
     .member = &AtmosphereParameters::mie_phase_g},
    {.name = "turbidity",
     .canonical_key = "turbidity",
     .unit = "",
     .description = "atmospheric (Linke-style) turbidity of the fitted models (the study: 2.53)",
     .default_value = 2.53,
     .min_value = 1.0,
     .max_value = 10.0,
     .member = &AtmosphereParameters::turbidity},
    {.name = "albedo",
     .canonical_key = "albedo",
     .unit = "",
     .description = "Lambertian ground albedo, a constant in [0, 1]; default 'grass': the "
                    "spectral albedo of grass (Feister and Grewe 1995) at each wavelength",
     .default_value = atmosphere_table_detail::kNoNumber,
     .default_text = "grass",
     .min_value = 0.0,
     .max_value = 1.0,
     .optional_member = &AtmosphereParameters::ground_albedo},
    // The absorbers of the broadband (300..4000 nm) irradiance (Bird and Riordan 1986,
    // models/atmosphere/spctral2.h). Defaults: the reference atmosphere of ASTM G-173-03 (the
    // U.S. Standard Atmosphere 1976: 1.42 cm of precipitable water, 0.34 atm-cm of ozone).
    {.name = "precipitable_water_cm",
     .canonical_key = "w",
     .unit = "cm",
     .description = "precipitable water of the vertical column (water vapour absorption of the "
                    "broadband irradiance)",
     .default_value = 1.42,
     .min_value = 0.0,
     .max_value = 10.0,
     .keys_models = false,
     .member = &AtmosphereParameters::precipitable_water_cm},
    {.name = "ozone_atm_cm",
     .canonical_key = "o3",
     .unit = "atm-cm",
     .description = "ozone column (ozone absorption of the broadband irradiance); 1 atm-cm = "
                    "1000 Dobson units",
     .default_value = 0.34,
     .min_value = 0.0,
     .max_value = 1.0,
     .keys_models = false,
     .member = &AtmosphereParameters::ozone_atm_cm},
}};

// The entry of a request name, or nullptr.
const AtmosphereParameterInfo* find_atmosphere_parameter(std::string_view name);

// Sets the parameter named name (request name); false when no atmosphere parameter has it.
bool set_atmosphere_parameter(AtmosphereParameters& atmosphere, std::string_view name,
                              double value);

// The descriptor entry of an atmosphere parameter, from the table. A model whose answers hold
// on a narrower range (Preetham's fit: turbidity >= 2) gives that range, which must lie within
// the table's; std::logic_error for an unknown name or a wider range (a descriptor bug).
ParameterSpec atmosphere_parameter_spec(std::string_view name);
ParameterSpec atmosphere_parameter_spec(std::string_view name, double min_value, double max_value);

}  // namespace clearsky
