// The atmosphere every physically based model shares (paper section "Model parameters";
// docs/architecture.md "The atmosphere"), as one parameter set with the study's values as
// defaults. The parameters are declared once, in atmosphere_parameter_table.h
// (docs/model-contract.md); this table restates them for the reader and is checked against it
// by tests/models/atmosphere/atmosphere_parameter_table_test.cpp (names, members, units,
// defaults, ranges).
//
// | name                         | member                       | unit | default | range           | meaning                                     |
// |------------------------------|------------------------------|------|---------|-----------------|---------------------------------------------|
// | earth_radius_m               | earth_radius_m               | m    | 6360e3  | (0, inf)        | ground sphere                               |
// | top_radius_m                 | top_radius_m                 | m    | 6420e3  | (0, inf)        | top of the atmosphere, > earth_radius_m     |
// | rayleigh_scale_height_m      | rayleigh_scale_height_m      | m    | 8000    | (0, 1e5]        | air density exp(-h/H)                       |
// | mie_scale_height_m           | mie_scale_height_m           | m    | 1200    | (0, 1e5]        | aerosol density exp(-h/H)                   |
// | rayleigh_temperature_celsius | rayleigh_temperature_celsius | C    | 15      | [-100, 100]     | Penndorf 0 C table x 273.16/(273.16+T)      |
// | alpha                        | angstrom_alpha               | -    | 0.8     | [0, 4]          | aerosol optical depth beta lambda_um^-alpha |
// | beta                         | angstrom_beta                | -    | 0.04    | [0, 2]          | aerosol optical depth at 1 um               |
// | mie_single_scattering_albedo | mie_single_scattering_albedo | -    | 0.8     | [0, 1]          | aerosol scattering / extinction             |
// | g                            | mie_phase_g                  | -    | 0.7     | [-0.999, 0.999] | Cornette-Shanks asymmetry                   |
// | turbidity                    | turbidity                    | -    | 2.53    | [1, 10]         | Linke-style turbidity (Preetham, Hosek)     |
// | albedo                       | ground_albedo                | -    | grass   | [0, 1]          | Lambertian ground reflectance               |
// | precipitable_water_cm        | precipitable_water_cm        | cm   | 1.42    | [0, 10]         | water vapour column (broadband only)        |
// | ozone_atm_cm                 | ozone_atm_cm                 | atm-cm | 0.34  | [0, 1]          | ozone column, 1000 DU (broadband only)      |
//
// The last two are applied after the model, by the broadband irradiance of /v1/irradiance
// (api/irradiance/broadband_irradiance.h, Bird and Riordan 1986): no model takes them, and they
// are not part of canonical_string() (no model's tables depend on them).
// "name" is the name in requests and in InvalidInput::field(). A model may narrow a range in
// its descriptor (Preetham: turbidity in [2, 10]). Value type; thread-safe. validate() is
// written so that NaN fails it.
#pragma once

#include <optional>
#include <string>

namespace clearsky {

struct AtmosphereParameters {
  // The defaults of atmosphere_parameter_table.h.
  AtmosphereParameters();

  double earth_radius_m;
  double top_radius_m;
  double rayleigh_scale_height_m;
  double mie_scale_height_m;
  double rayleigh_temperature_celsius;
  double angstrom_alpha;
  double angstrom_beta;
  double mie_single_scattering_albedo;
  double mie_phase_g;
  double turbidity;
  // Empty: the spectral albedo of grass (Feister and Grewe 1995); otherwise a constant.
  std::optional<double> ground_albedo;
  double precipitable_water_cm;
  double ozone_atm_cm;

  // Throws InvalidInput (models/core/invalid_input.h) naming the offending parameter.
  void validate() const;
  // Every value, in a fixed order and full precision, for cache keys.
  std::string canonical_string() const;
  bool operator==(const AtmosphereParameters&) const = default;
};

}  // namespace clearsky
