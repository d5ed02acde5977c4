// A spectrum from a chromaticity with the CIE daylight basis: S = S0 + M1 S1 + M2 S2, with
// M1, M2 from (x, y) (CIE 15:2004 eq. 3.7; Preetham et al. 1999 appendix), then scaled so its
// radiometric Y equals the requested one. Used by Preetham and by the paper's 3-sample
// spectrum reconstruction (section "Spectrum sampling").
#pragma once

#include "models/colour/colour_spaces.h"
#include "models/spectral/spectrum.h"
#include "models/spectral/wavelength_grid.h"

namespace clearsky {

struct DaylightWeights {
  double m1 = 0, m2 = 0;
};

DaylightWeights daylight_weights(double chroma_x, double chroma_y);

// The relative daylight spectrum S0 + M1 S1 + M2 S2 on grid (point samples, held beyond the
// table's 360..830 nm).
Spectrum daylight_relative_spectrum(const DaylightWeights& weights, const WavelengthGrid& grid);

// The daylight spectrum of chromaticity (x, y) whose Y (integral of y_bar L on grid) is
// xyy.luminance_y. Black (Y <= 0) gives zeros.
Spectrum daylight_spectrum(const Xyy& xyy, const WavelengthGrid& grid);

}  // namespace clearsky
