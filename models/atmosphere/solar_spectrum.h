// The extraterrestrial solar spectral irradiance (W/(m2.nm)) on a wavelength grid, as the
// 2016 study used it: averaged over each bin of a bin grid (for the paper's 40 bins this is
// exactly models/data/spectra/solar_irradiance_40bins.csv, the mean of the ASTM rows in each
// bin); for a point wavelength inside 360..818.25 nm, linear interpolation of that 40-bin
// table (the study's rule for tabulated inputs), elsewhere the mean of the ASTM rows within the
// paper's bin width centred on it, so that a point never lands on a single Fraunhofer line.
// Source: ASTM G-173-03 extraterrestrial column.
#pragma once

#include "models/spectral/spectrum.h"
#include "models/spectral/wavelength_grid.h"

namespace clearsky {

inline constexpr double kPointSolarWindowNm = 11.75;

// The point wavelengths whose window lies within the ASTM G-173 rows (280..4000 nm, the last
// row's 5 nm step included): the spectral range of every model built on AtmosphereSpectra.
inline constexpr double kSolarSpectrumMinNm = 280.0 + 0.5 * kPointSolarWindowNm;
inline constexpr double kSolarSpectrumMaxNm = 4005.0 - 0.5 * kPointSolarWindowNm;

// Throws InvalidInput("wavelengths", ...) for a wavelength whose window leaves ASTM G-173.
double solar_spectrum_at_point_nm(double wavelength_nm);
Spectrum solar_irradiance_on(const WavelengthGrid& grid);

}  // namespace clearsky
