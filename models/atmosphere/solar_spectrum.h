// The extraterrestrial solar spectral irradiance (W/(m2.nm)) on a wavelength grid, as the
// 2016 study used it: averaged over each bin of a bin grid (for the paper's 40 bins this is
// exactly models/data/spectra/solar_irradiance_40bins.csv), and for a point wavelength the
// average over the paper's bin width (11.75 nm) centred on it, so that point samples do not
// land on individual Fraunhofer lines. Source: ASTM G-173-03 extraterrestrial column.
#pragma once

#include "models/spectral/spectrum.h"
#include "models/spectral/wavelength_grid.h"

namespace clearsky {

inline constexpr double kPointSolarWindowNm = 11.75;

// Throws std::out_of_range for wavelengths outside ASTM G-173 (280..4000 nm).
double solar_spectrum_at_point_nm(double wavelength_nm);
Spectrum solar_irradiance_on(const WavelengthGrid& grid);

}  // namespace clearsky
