// Spectral coefficients of the atmosphere on a grid.
#include "models/atmosphere/atmosphere_spectra.h"

#include <cmath>

#include "models/atmosphere/solar_spectrum.h"
#include "models/spectral/reference_spectra.h"

namespace clearsky {

AtmosphereSpectra AtmosphereSpectra::build(const AtmosphereParameters& p,
                                           const WavelengthGrid& grid) {
  p.validate();
  const auto& ref = ReferenceSpectra::get();
  AtmosphereSpectra s;
  s.parameters = p;
  s.grid = grid;
  constexpr double kZeroCelsius = 273.16;  // the study's ratio 273.16 / 288.16 at 15 C
  s.rayleigh_scattering_per_m = ref.rayleigh_penndorf_0c_per_m.resample(
                                    grid, Resampling::point, OutOfRange::hold_end_values) *
                                (kZeroCelsius / (kZeroCelsius + p.rayleigh_temperature_celsius));
  s.mie_extinction_per_m = Spectrum(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    s.mie_extinction_per_m[i] =
        p.angstrom_beta * std::pow(grid[i] / 1000.0, -p.angstrom_alpha) / p.mie_scale_height_m;
  }
  s.mie_scattering_per_m = s.mie_extinction_per_m * p.mie_single_scattering_albedo;
  s.ground_albedo = p.ground_albedo ? Spectrum(grid.size(), *p.ground_albedo)
                                    : ref.grass_albedo.resample(grid, Resampling::point,
                                                                OutOfRange::hold_end_values);
  s.solar_irradiance_w_m2_nm = solar_irradiance_on(grid);
  return s;
}

double AtmosphereSpectra::rayleigh_density(double altitude_m) const {
  return std::exp(-altitude_m / parameters.rayleigh_scale_height_m);
}

double AtmosphereSpectra::mie_density(double altitude_m) const {
  return std::exp(-altitude_m / parameters.mie_scale_height_m);
}

}  // namespace clearsky
