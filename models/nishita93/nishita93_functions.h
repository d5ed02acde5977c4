// Nishita93's per-ray single scattering (Nishita et al. 1993, section 4;
// models/nishita93/README.md): the view ray is sampled where it crosses the spheres of the tables
// (plus the observer, the ray's tangent point when it passes one, and the end of the segment), and
//   L = E_sun [beta_R P_R(nu) I_R + beta_M,sca P_CS(nu) I_M],
//   I_p = trapezoid over the samples of rho_p(x) exp(-(beta_R (L_R,view + L_R,sun) +
//                                                    beta_M,ext (L_M,view + L_M,sun))),
// where the observer-side optical lengths L_view are accumulated incrementally with the
// trapezoid rule over the same samples and L_sun come from the tables (0 contribution in the
// Earth's shadow). Transmittance is Rayleigh scattering plus Mie extinction.
//
// Differences from the study's code, which only handled upward views from inside the
// atmosphere: downward views (through the lower spheres, to the ground or the tangent point),
// observers above the atmosphere (from where the ray enters it), and the observer's own sample
// carrying its real integrand. The study's code started the trapezoid with 0 there (its
// previous-sample variables began at zero), which drops half of the first layer's light;
// study_viewer_sample = true reproduces that (RMSE 26.49 on the 15 public captures, exactly
// the study's; 25.38 without it).
// Pure functions; thread-safe.
#pragma once

#include <limits>
#include <span>

#include "models/atmosphere/atmosphere_spectra.h"
#include "models/core/ray_scattering.h"
#include "models/core/weighted_transmittance_sums.h"
#include "models/nishita93/nishita93_tables.h"

namespace clearsky::nishita93 {

// Scratch space for one ray (no allocation per ray), each of the grid size.
struct RayWorkspace {
  std::span<double> rayleigh_integral, mie_integral;
};

// Writes the in-scattered radiance into radiance_out and the transmittance of the segment
// into transmittance_out (both of the atmosphere's grid size; transmittance_out may be
// empty). The segment ends at the ground, the top of the atmosphere, or max_distance_m.
// Returns whether it ends on the ground. kernel: the exponential of the samples' transmittances
// (weighted_transmittance_sums.h; the model uses the default, tests compare it with the other).
bool single_scattering(const Nishita93Tables& tables, const AtmosphereSpectra& atmosphere,
                       const RaySunGeometry& ray, double max_distance_m,
                       std::span<double> radiance_out, std::span<double> transmittance_out,
                       const RayWorkspace& workspace, bool study_viewer_sample = false,
                       TransmittanceKernel kernel = TransmittanceKernel::float_polynomial);

// Convenience form that allocates its results.
ScatteringAlongRay single_scattering(
    const Nishita93Tables& tables, const AtmosphereSpectra& atmosphere, const RaySunGeometry& ray,
    double max_distance_m = std::numeric_limits<double>::infinity(),
    bool study_viewer_sample = false,
    TransmittanceKernel kernel = TransmittanceKernel::float_polynomial);

// Transmittance from a point to the sun through the tables (0 in the Earth's shadow).
void sun_transmittance(const Nishita93Tables& tables, const AtmosphereSpectra& atmosphere,
                       double r_m, double mu_s, std::span<double> out);

}  // namespace clearsky::nishita93
