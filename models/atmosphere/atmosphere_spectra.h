// The spectral quantities of an AtmosphereParameters on a wavelength grid, as the 2016 study
// computed them (docs/architecture.md "The atmosphere"):
//  - Rayleigh sea-level scattering = extinction: Penndorf (0 C) x 273.16 / (273.16 + T),
//    point-sampled and held beyond 360..830 nm (e.g. 6.678e-5 /m at 360 nm for 15 C);
//  - aerosol (Mie) sea-level extinction beta (lambda / 1000 nm)^-alpha / H_M, scattering the
//    single-scattering albedo times that;
//  - ground albedo: grass, point-sampled and held beyond 800 nm, or a constant;
//  - solar irradiance: solar_spectrum.h.
// Densities at altitude h: exp(-h / H). Immutable value; thread-safe.
#pragma once

#include "models/atmosphere/atmosphere_parameters.h"
#include "models/spectral/spectrum.h"
#include "models/spectral/wavelength_grid.h"

namespace clearsky {

struct AtmosphereSpectra {
  AtmosphereParameters parameters;
  WavelengthGrid grid = WavelengthGrid::paper_bins();
  Spectrum rayleigh_scattering_per_m;  // at sea level
  Spectrum mie_extinction_per_m;       // at sea level
  Spectrum mie_scattering_per_m;       // at sea level
  Spectrum ground_albedo;
  Spectrum solar_irradiance_w_m2_nm;  // extraterrestrial, normal incidence

  // Validates the parameters (std::invalid_argument naming the parameter).
  static AtmosphereSpectra build(const AtmosphereParameters& parameters,
                                 const WavelengthGrid& grid);

  double rayleigh_density(double altitude_m) const;
  double mie_density(double altitude_m) const;
};

}  // namespace clearsky
