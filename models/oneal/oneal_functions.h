// O'Neal's per-ray single scattering (O'Neil, "Accurate Atmospheric Scattering", GPU Gems 2,
// 2005, chapter 16; paper section "O'Neal Model"; models/oneal/README.md), with the
// 2016 study's changes: separate Rayleigh and Mie scale heights, the Rayleigh phase function,
// and O'Neil's fitted scale function replaced by Schuler's approximation of the Chapman
// function (Schuler 2012, GPU Pro 3):
//   optical length from a point of relative density rho to infinity along zenith cosine
//   mu >= 0:   rho * scale(H, mu),   scale(H, mu) = H c / (c mu + 1),   c = sqrt(R / H),
// with R the ground radius. The view segment is cut into n equal parts (the study: 4; O'Neil:
// 2) sampled at their midpoints; at each, the optical length from the observer is the
// difference of the optical lengths to infinity of the observer and of the sample along the
// view, plus the sample's optical length to the sun.
//
// Beyond the study (which only handled upward views from inside the atmosphere and the sun
// above the horizon): for mu < 0 the Chapman identity
//   L(r, mu) = 2 rho(r_t) scale(H, 0) - rho(r) scale(H, -mu),  r_t = r sqrt(1 - mu^2),
// (the whole chord through the tangent point minus the part behind the point), the Earth's
// shadow (a sun ray that meets the ground contributes nothing), views that meet the ground
// (their segment lengths are measured along the reversed, upward ray), observers above the
// atmosphere (the segment starts where the view enters it) and aerial perspective.
// Pure functions; thread-safe.
#pragma once

#include <limits>
#include <optional>
#include <span>

#include "models/atmosphere/atmosphere_spectra.h"
#include "models/core/optical_depth.h"
#include "models/core/ray_scattering.h"
#include "models/core/weighted_transmittance_sums.h"

namespace clearsky::oneal {

// Schuler's scale function H c / (c mu + 1), c = sqrt(R / H), for mu in [0, 1] (metres).
double scale_m(double scale_height_m, double bottom_radius_m, double mu);

// Optical lengths from the point (r_m, mu) to infinity along the ray, by the approximation
// above; nothing when the ray meets the ground.
std::optional<OpticalLengths> optical_lengths_to_infinity(const AtmosphereParameters& atmosphere,
                                                          double r_m, double mu);

// Scratch space for one ray, each of the grid size.
struct RayWorkspace {
  std::span<double> rayleigh_integral, mie_integral;
};

// Single scattering along the view with `samples` midpoint samples: writes the in-scattered
// radiance, and the segment's transmittance when transmittance_out is not empty. The segment
// ends at the ground, the top of the atmosphere, or max_distance_m. Returns whether it ends
// on the ground. kernel: the exponential of the samples' transmittances
// (weighted_transmittance_sums.h; the model uses the default, tests compare it with the other).
bool single_scattering(const AtmosphereSpectra& atmosphere, const RaySunGeometry& ray, int samples,
                       double max_distance_m, std::span<double> radiance_out,
                       std::span<double> transmittance_out, const RayWorkspace& workspace,
                       TransmittanceKernel kernel = TransmittanceKernel::float_polynomial);

ScatteringAlongRay single_scattering(
    const AtmosphereSpectra& atmosphere, const RaySunGeometry& ray, int samples,
    double max_distance_m = std::numeric_limits<double>::infinity(),
    TransmittanceKernel kernel = TransmittanceKernel::float_polynomial);

}  // namespace clearsky::oneal
