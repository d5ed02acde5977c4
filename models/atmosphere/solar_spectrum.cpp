// Solar spectrum resampling from the full ASTM G-173 table.
#include "models/atmosphere/solar_spectrum.h"

#include "models/spectral/reference_spectra.h"

namespace clearsky {

double solar_spectrum_at_point_nm(double wavelength_nm) {
  const auto& astm = ReferenceSpectra::get().astm_g173_extraterrestrial;
  const double half = 0.5 * kPointSolarWindowNm;
  return astm.bin_average(wavelength_nm - half, wavelength_nm + half, OutOfRange::error);
}

Spectrum solar_irradiance_on(const WavelengthGrid& grid) {
  if (grid.kind() == WavelengthGrid::Kind::bins) {
    return ReferenceSpectra::get().astm_g173_extraterrestrial.resample(grid, Resampling::bin_average,
                                                                      OutOfRange::error);
  }
  Spectrum out(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) out[i] = solar_spectrum_at_point_nm(grid[i]);
  return out;
}

}  // namespace clearsky
