// The aerosol optics of one AERONET phase-function inversion (models/aeronet) on a model's
// wavelength grid, for the Bruneton engine (AerosolOptics, models/bruneton/bruneton.h):
//  - the retrieval: the one nearest in time to retrieval_time_utc_h (hours UTC of the
//    inversion's day; the earlier of two equally near), or for a negative time the mean of
//    the day's retrievals (their tau440, alpha440-870 and phase functions averaged: the mean
//    of normalised phase functions is normalised). Not interpolated in time: the retrievals
//    are 30 minutes to an hour apart and most captures of a day fall outside their span;
//  - the optical depth: the retrieval's Angstrom law tau440 (lambda / 440 nm)^-alpha440-870,
//    times aod_scale, over the atmosphere's aerosol scale height (sea-level extinction
//    tau / H_M, as AtmosphereSpectra does for beta); the same law beyond 440..870 nm;
//  - scattering: the extinction times the atmosphere's mie_single_scattering_albedo (the .pfn
//    file carries no single-scattering albedo: its albedo_* columns are the surface albedo);
//  - the phase function per wavelength: the retrieval's phase functions (log-linear in angle,
//    normalised, models/atmosphere/tabulated_phase_function.h) interpolated linearly between
//    its wavelengths and held beyond 442 and 1020 nm (spectral_phase_function.h);
//  - the precomputation's single phase function (orders >= 2): the one at 550 nm.
// Pure functions; thread-safe.
#pragma once

#include <cstddef>
#include <string>

#include "models/aeronet/aeronet_phase_functions.h"
#include "models/atmosphere/atmosphere_spectra.h"
#include "models/bruneton/bruneton.h"

namespace clearsky {

// The wavelength of the precomputation's phase function.
inline constexpr double kPrecomputationPhaseWavelengthNm = 550.0;

// The retrieval the time selects: its index in file.retrievals, or file.retrievals.size() for
// the mean (negative time).
std::size_t select_retrieval(const aeronet::PhaseFunctionFile& file, double retrieval_time_utc_h);

// The retrieval (index, or retrievals.size() for the mean) as one retrieval.
aeronet::PhaseFunctionRetrieval selected_retrieval(const aeronet::PhaseFunctionFile& file,
                                                   std::size_t selection);

// The optics on atmosphere.grid; description and cache prefix name the inversion's content hash,
// the retrieval and aod_scale.
AerosolOptics measured_aerosol_optics(const aeronet::PhaseFunctionFile& file,
                                      double retrieval_time_utc_h, double aod_scale,
                                      const AtmosphereSpectra& atmosphere);

}  // namespace clearsky
