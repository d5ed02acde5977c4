// CIE daylight reconstruction.
#include "models/colour/daylight_spectrum.h"

#include "models/spectral/reference_spectra.h"

namespace clearsky {

DaylightWeights daylight_weights(double x, double y) {
  const double m = 0.0241 + 0.2562 * x - 0.7341 * y;
  return {(-1.3515 - 1.7703 * x + 5.9114 * y) / m, (0.0300 - 31.4424 * x + 30.0717 * y) / m};
}

Spectrum daylight_relative_spectrum(const DaylightWeights& w, const WavelengthGrid& grid) {
  const auto& ref = ReferenceSpectra::get();
  Spectrum s = ref.daylight_s0.resample(grid, Resampling::point, OutOfRange::hold_end_values);
  const Spectrum s1 =
      ref.daylight_s1.resample(grid, Resampling::point, OutOfRange::hold_end_values);
  const Spectrum s2 =
      ref.daylight_s2.resample(grid, Resampling::point, OutOfRange::hold_end_values);
  for (std::size_t i = 0; i < grid.size(); ++i) s[i] += w.m1 * s1[i] + w.m2 * s2[i];
  return s;
}

Spectrum daylight_spectrum(const Xyy& xyy, const WavelengthGrid& grid) {
  if (!(xyy.luminance_y > 0.0)) return Spectrum(grid.size(), 0.0);
  Spectrum s = daylight_relative_spectrum(daylight_weights(xyy.chroma_x, xyy.chroma_y), grid);
  const double y = spectrum_to_xyz(s, grid).y;
  if (!(y > 0.0)) return Spectrum(grid.size(), 0.0);
  s *= xyy.luminance_y / y;
  return s;
}

}  // namespace clearsky
