// Optical depth and transmittance along rays through the paper's atmosphere: two exponential
// density profiles exp(-h/H) (Rayleigh H_R, Mie H_M) above a ground sphere, inside a top
// sphere (docs/architecture.md "The atmosphere"). Extinction is Rayleigh scattering plus Mie
// extinction (no absorbing gas), so the transmittance of a path is
//   T = exp(-(beta_R L_R + beta_M,ext L_M)),
// with L the "optical lengths" (integrals of relative density along the path, metres).
//
// Two levels of precision share one code path (ray_quadrature.h): the default options give
// ~1e-9 relative error at a moderate cost, RayQuadratureOptions::reference() rounding-level
// error for tests of the models' fast paths. vertical_optical_length_m() is the closed form
// the numerical integration is tested against.
// All functions are pure and thread-safe.
#pragma once

#include <optional>

#include "models/atmosphere/atmosphere_spectra.h"
#include "models/core/ray_quadrature.h"
#include "models/spectral/spectrum.h"

namespace clearsky {

// Integral of exp(-(radius - bottom_radius_m) / scale_height_m) along the ray (r_m, mu) over
// distances [0, distance_m] (ray_scattering.h parameterisation), in metres. No top: the
// caller chooses distance_m (e.g. to the top of the atmosphere).
double exponential_optical_length_m(double r_m, double mu, double distance_m,
                                    double bottom_radius_m, double scale_height_m,
                                    const RayQuadratureOptions& options = {});

// Closed form of the same integral along a vertical ray from altitude h0_m up to h1_m:
// H (exp(-h0/H) - exp(-h1/H)).
double vertical_optical_length_m(double h0_m, double h1_m, double scale_height_m);

struct OpticalLengths {
  double rayleigh_m = 0;
  double mie_m = 0;
  OpticalLengths& operator+=(const OpticalLengths& o) {
    rayleigh_m += o.rayleigh_m;
    mie_m += o.mie_m;
    return *this;
  }
};

// Both optical lengths along the ray (r_m, mu) over [0, distance_m].
OpticalLengths optical_lengths(const AtmosphereSpectra& atmosphere, double r_m, double mu,
                               double distance_m, const RayQuadratureOptions& options = {});

// Whether the ray (r_m, mu) from a point at or above the ground meets the ground sphere: the
// sun seen along it is hidden by the Earth.
bool ray_hits_ground(double r_m, double mu, double bottom_radius_m);

// Optical lengths from the point (r_m, mu) to space along the ray, through the part of it
// inside the top sphere (zero when it misses the atmosphere); nothing when the ray meets the
// ground (the point is in the Earth's shadow for a light source in that direction).
std::optional<OpticalLengths> optical_lengths_to_space(const AtmosphereSpectra& atmosphere,
                                                       double r_m, double mu,
                                                       const RayQuadratureOptions& options = {});

// exp(-(beta_R L_R + beta_M,ext L_M)) on the atmosphere's grid.
Spectrum transmittance(const AtmosphereSpectra& atmosphere, const OpticalLengths& lengths);
// The same, written into out (size = grid size); no allocation.
void transmittance_into(const AtmosphereSpectra& atmosphere, const OpticalLengths& lengths,
                        double* out);

// Transmittance from the point (r_m, mu) to space; zero in the Earth's shadow.
Spectrum transmittance_to_space(const AtmosphereSpectra& atmosphere, double r_m, double mu,
                                const RayQuadratureOptions& options = {});

}  // namespace clearsky
