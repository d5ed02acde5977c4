// Aerosol optics from an AERONET inversion (measured_aerosol_optics.h).
#include "models/measured_aerosols/measured_aerosol_optics.h"

#include <cmath>
#include <sstream>

#include "models/core/content_hash.h"

namespace clearsky {

std::size_t select_retrieval(const aeronet::PhaseFunctionFile& file, double retrieval_time_utc_h) {
  if (retrieval_time_utc_h < 0.0) return file.retrievals.size();
  std::size_t best = 0;
  for (std::size_t i = 1; i < file.retrievals.size(); ++i) {
    if (std::abs(file.retrievals[i].time_utc_h - retrieval_time_utc_h) <
        std::abs(file.retrievals[best].time_utc_h - retrieval_time_utc_h))
      best = i;
  }
  return best;
}

aeronet::PhaseFunctionRetrieval selected_retrieval(const aeronet::PhaseFunctionFile& file,
                                                   std::size_t selection) {
  if (selection < file.retrievals.size()) return file.retrievals[selection];
  aeronet::PhaseFunctionRetrieval mean = file.retrievals.front();
  mean.time = "mean";
  const double n = static_cast<double>(file.retrievals.size());
  mean.time_utc_h = 0.0;
  mean.aod_440 = 0.0;
  mean.angstrom_440_870 = 0.0;
  for (auto& row : mean.phase)
    for (double& v : row) v = 0.0;
  for (const auto& r : file.retrievals) {
    mean.time_utc_h += r.time_utc_h / n;
    mean.aod_440 += r.aod_440 / n;
    mean.angstrom_440_870 += r.angstrom_440_870 / n;
    for (std::size_t w = 0; w < r.phase.size(); ++w)
      for (std::size_t a = 0; a < r.phase[w].size(); ++a) mean.phase[w][a] += r.phase[w][a] / n;
  }
  return mean;
}

AerosolOptics measured_aerosol_optics(const aeronet::PhaseFunctionFile& file,
                                      double retrieval_time_utc_h, double aod_scale,
                                      const AtmosphereSpectra& atmosphere) {
  const std::size_t selection = select_retrieval(file, retrieval_time_utc_h);
  const aeronet::PhaseFunctionRetrieval r = selected_retrieval(file, selection);
  const WavelengthGrid& grid = atmosphere.grid;
  AerosolOptics optics;
  optics.mie_extinction_per_m = Spectrum(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i)
    optics.mie_extinction_per_m[i] =
        aod_scale * r.aod_at(grid[i]) / atmosphere.parameters.mie_scale_height_m;
  optics.mie_scattering_per_m =
      optics.mie_extinction_per_m * atmosphere.parameters.mie_single_scattering_albedo;
  std::vector<TabulatedPhaseFunction> phase;
  for (const auto& row : r.phase) phase.emplace_back(file.angles_deg, row);
  const auto spectral =
      std::make_shared<const SpectralPhaseFunction>(file.wavelengths_nm, std::move(phase), grid);
  optics.precomputation_phase = std::make_shared<const TabulatedPhaseFunction>(
      spectral->at_wavelength(kPrecomputationPhaseWavelengthNm));
  optics.phase = spectral;
  std::ostringstream d;
  d.precision(17);
  d << "measured_aerosols;inversion=" << hex64(file.content_hash) << ";retrieval="
    << (selection < file.retrievals.size() ? std::to_string(selection) : std::string("mean"))
    << ";aod_scale=" << aod_scale << ";phase_nm=" << kPrecomputationPhaseWavelengthNm;
  optics.description = d.str();
  optics.cache_prefix = "measured_aerosols";
  return optics;
}

}  // namespace clearsky
