// Sampling directions and binned phase-function integrals of Nishita96 (see
// nishita96_functions.h).
#include "models/nishita96/nishita96_functions.h"

#include <cmath>

#include "models/atmosphere/phase_functions.h"
#include "models/core/numeric.h"

namespace clearsky::nishita96 {

std::array<double, kSamplingDirections> sampling_angles_rad(double sun_zenith_rad) {
  const double half_pi = 0.5 * kPi;
  return {0.0,          kPi, half_pi, -half_pi, sun_zenith_rad, sun_zenith_rad + kPi, sun_zenith_rad - half_pi,
          sun_zenith_rad + half_pi};
}

PhaseIntegrals binned_phase_integrals(Vec3 view, const std::array<Vec3, kSamplingDirections>& sampling_directions,
                                      double mie_g, int theta_cells) {
  PhaseIntegrals result;
  const double d_theta = kPi / theta_cells;
  const double d_phi = kPi / theta_cells;
  for (int i = 0; i < theta_cells; ++i) {
    const double theta = (i + 0.5) * d_theta;
    const double sin_theta = std::sin(theta);
    const double cos_theta = std::cos(theta);
    const double solid_angle = sin_theta * d_theta * d_phi;
    for (int j = 0; j < 2 * theta_cells; ++j) {
      const double phi = (j + 0.5) * d_phi;
      const Vec3 w{std::cos(phi) * sin_theta, std::sin(phi) * sin_theta, cos_theta};
      const double mu = clamp_cosine(dot(view, w));
      int nearest = 0;
      double best = dot(w, sampling_directions[0]);
      for (int k = 1; k < kSamplingDirections; ++k) {
        const double candidate = dot(w, sampling_directions[k]);
        if (candidate > best) {
          best = candidate;
          nearest = k;
        }
      }
      result.rayleigh[nearest] += rayleigh_phase(mu) * solid_angle;
      result.mie[nearest] += cornette_shanks_phase(mu, mie_g) * solid_angle;
    }
  }
  return result;
}

}  // namespace clearsky::nishita96
