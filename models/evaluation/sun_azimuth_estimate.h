// The sun azimuth of a measured sky, estimated from the sky's mirror symmetry about the sun's
// vertical plane, as the 2016 study did because the azimuth of Kider's instrument drifts while
// the zenith from time and place matches (models/evaluation/README.md). For each
// candidate azimuth a (computed - 20, computed - 19.8, ... up to the first >= computed + 20
// degrees), the error is the sum over 16 view zeniths acos((i + 0.5) / 16) and 64 view
// azimuths j * 360 / 64 of |integral over wavelength of (L(zenith, phi) - L(zenith, 2a - phi))|,
// with L the measured sky interpolated over the hemisphere (concentric_sky_interpolant.h) and
// the wavelength integral the sum of the grid's point samples times their integration weights;
// the smallest error wins, the first on ties.
#pragma once

#include "models/evaluation/measured_sky.h"
#include "models/spectral/wavelength_grid.h"

namespace clearsky {

struct SunAzimuthSearch {
  double half_range_deg = 20.0;
  double step_deg = 0.2;
  WavelengthGrid wavelengths = WavelengthGrid::paper_bins();
};

struct SunAzimuthEstimate {
  double azimuth_deg = 0;     // clockwise from North, in [0, 360)
  double symmetry_error = 0;  // the minimal error, W/(m2.sr) summed over the 1024 directions
  int candidates = 0;         // number of azimuths tried
};

// Estimate around computed_azimuth_deg for a capture of the 81-direction layout (repair its
// defective samples first, as the study did). Throws std::invalid_argument for another layout
// or invalid search parameters.
SunAzimuthEstimate estimate_sun_azimuth(const MeasuredCapture& capture, double computed_azimuth_deg,
                                        const SunAzimuthSearch& search = {});

}  // namespace clearsky
