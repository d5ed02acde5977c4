// Solar spectrum resampling from the full ASTM G-173 table. A "bin average" here is, as in
// the 2016 study (its 40-bin table is reproduced exactly), the mean of the table's rows whose
// wavelength lies in [lo, hi); a bin holding no row takes the interpolated value at its centre.
#include "models/atmosphere/solar_spectrum.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "models/core/invalid_input.h"
#include "models/spectral/reference_spectra.h"

namespace clearsky {

namespace {

double mean_of_rows(double lo_nm, double hi_nm) {
  const auto& astm = ReferenceSpectra::get().astm_g173_extraterrestrial;
  if (lo_nm < astm.min_nm() || hi_nm > astm.max_nm() + 5.0) {
    throw InvalidInput("wavelengths", "the solar spectrum over [" + std::to_string(lo_nm) + ", " +
                                          std::to_string(hi_nm) +
                                          "] nm is outside ASTM G-173 (280..4000 nm)");
  }
  const auto& nm = astm.wavelengths_nm();
  const auto first = std::lower_bound(nm.begin(), nm.end(), lo_nm);
  const auto last = std::lower_bound(nm.begin(), nm.end(), hi_nm);
  if (first == last) return astm.at(0.5 * (lo_nm + hi_nm), OutOfRange::hold_end_values);
  double sum = 0.0;
  for (auto it = first; it != last; ++it)
    sum += astm.values()[static_cast<std::size_t>(it - nm.begin())];
  return sum / static_cast<double>(last - first);
}

}  // namespace

double solar_spectrum_at_point_nm(double wavelength_nm) {
  // Inside the paper's grid, the study's rule for tabulated inputs: linear interpolation of the
  // 40-bin table, each bin value standing at its bin's start (docs/architecture.md "Conventions
  // and units").
  const auto& bins = ReferenceSpectra::get().solar_irradiance_40_bins;
  if (wavelength_nm >= bins.min_nm() && wavelength_nm <= bins.max_nm()) {
    return bins.at(wavelength_nm, OutOfRange::error);
  }
  const double half = 0.5 * kPointSolarWindowNm;
  return mean_of_rows(wavelength_nm - half, wavelength_nm + half);
}

Spectrum solar_irradiance_on(const WavelengthGrid& grid) {
  Spectrum out(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    out[i] = grid.kind() == WavelengthGrid::Kind::bins
                 ? mean_of_rows(grid.lower_edge_nm(i), grid.upper_edge_nm(i))
                 : solar_spectrum_at_point_nm(grid[i]);
  }
  return out;
}

}  // namespace clearsky
