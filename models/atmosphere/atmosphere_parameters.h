// The atmosphere every physically based model shares (paper section "Model parameters";
// docs/architecture.md "The atmosphere"), as one parameter set with the study's values as defaults.
//
// | name                         | unit | default | valid range     | meaning                                  |
// |------------------------------|------|---------|-----------------|------------------------------------------|
// | earth_radius_m               | m    | 6360e3  | (0, inf)        | ground sphere                            |
// | top_radius_m                 | m    | 6420e3  | > earth radius  | top of the atmosphere                    |
// | rayleigh_scale_height_m      | m    | 8000    | (0, 1e5]        | air density exp(-h/H)                    |
// | mie_scale_height_m           | m    | 1200    | (0, 1e5]        | aerosol density exp(-h/H)                |
// | rayleigh_temperature_celsius | C    | 15      | [-100, 100]     | Penndorf 0 C table x 273.16/(273+T)       |
// | angstrom_alpha               | -    | 0.8     | [0, 4]          | aerosol optical depth beta lambda_um^-alpha |
// | angstrom_beta                | -    | 0.04    | [0, 2]          | aerosol optical depth at 1 um            |
// | mie_single_scattering_albedo | -    | 0.8     | [0, 1]          | aerosol scattering / extinction          |
// | mie_phase_g                  | -    | 0.7     | (-1, 1)         | Cornette-Shanks asymmetry                |
// | turbidity                    | -    | 2.53    | [1, 10]         | Linke-style turbidity (Preetham, Hosek)  |
// | ground_albedo                | -    | grass   | [0, 1] or grass | Lambertian ground reflectance            |
//
// Value type; thread-safe. validate() is written so that NaN fails it.
#pragma once

#include <optional>
#include <string>

namespace clearsky {

struct AtmosphereParameters {
  double earth_radius_m = 6360e3;
  double top_radius_m = 6420e3;
  double rayleigh_scale_height_m = 8000.0;
  double mie_scale_height_m = 1200.0;
  double rayleigh_temperature_celsius = 15.0;
  double angstrom_alpha = 0.8;
  double angstrom_beta = 0.04;
  double mie_single_scattering_albedo = 0.8;
  double mie_phase_g = 0.7;
  double turbidity = 2.53;
  // Empty: the spectral albedo of grass (Feister and Grewe 1995); otherwise a constant.
  std::optional<double> ground_albedo;

  // Throws InvalidInput (models/core/invalid_input.h) naming the offending parameter.
  void validate() const;
  // Every value, in a fixed order and full precision, for cache keys.
  std::string canonical_string() const;
  bool operator==(const AtmosphereParameters&) const = default;
};

}  // namespace clearsky
