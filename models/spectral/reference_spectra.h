// The physical tables of models/data as spectra, parsed once on first use (thread-safe static
// initialisation). Sources: see models/data/spectra/SOURCES.md.
#pragma once

#include "models/spectral/tabulated_spectrum.h"

namespace clearsky {

struct ReferenceSpectra {
  TabulatedSpectrum cie_x_bar, cie_y_bar, cie_z_bar;        // CIE 1931 2-degree, 5 nm
  TabulatedSpectrum daylight_s0, daylight_s1, daylight_s2;  // CIE 15:2004 Table T.2
  TabulatedSpectrum astm_g173_extraterrestrial;             // W/(m2.nm), 280..4000 nm
  TabulatedSpectrum solar_irradiance_40_bins;               // W/(m2.nm), bin starts 360..818.25 nm
  TabulatedSpectrum rayleigh_penndorf_0c_per_m;             // 1/m, sea level, 0 C
  TabulatedSpectrum grass_albedo;                           // Feister and Grewe 1995
  // Bird and Riordan 1986 (SPCTRAL2) Table 1, 300..4000 nm: extraterrestrial spectrum at 1 au
  // (W/(m2.nm)) and the absorption coefficients of water vapour (1/cm of precipitable water),
  // ozone (1/atm-cm) and the uniformly mixed gases (dimensionless, per unit pressure air mass).
  TabulatedSpectrum spctral2_extraterrestrial;
  TabulatedSpectrum spctral2_water_vapour_a_w;
  TabulatedSpectrum spctral2_ozone_a_o;
  TabulatedSpectrum spctral2_mixed_gases_a_u;

  static const ReferenceSpectra& get();
};

}  // namespace clearsky
