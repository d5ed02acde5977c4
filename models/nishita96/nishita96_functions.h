// Pure functions of the Nishita96 model's double scattering (Nishita et al. 1996; paper
// section "Nishita96 Model"; models/nishita96/README.md): the 8 sampling directions in
// the sun's vertical plane and the phase functions integrated over the solid angle of each.
//
// Frame: z up, x towards the sun's azimuth; the sun is (sin sz, 0, cos sz). A direction in the
// sun's vertical plane is given by a signed angle a from the zenith: (sin a, 0, cos a).
#pragma once

#include <array>
#include <vector>

#include "models/core/geometry.h"

namespace clearsky::nishita96 {

inline constexpr int kSamplingDirections = 8;

// The angles a of the sampling directions, in the study's order: zenith, nadir, the two
// horizontals (+x, -x), the sun, the anti-sun, and the sun rotated by -90 and +90 degrees.
std::array<double, kSamplingDirections> sampling_angles_rad(double sun_zenith_rad);
inline Vec3 direction_of_angle(double a_rad) { return {std::sin(a_rad), 0.0, std::cos(a_rad)}; }

// Integrals over the sphere of the Rayleigh and Cornette-Shanks phase functions of the angle
// between `view` (unit, observer towards the scattering point) and each incoming direction w,
// each w credited to its NEAREST sampling direction (largest dot product, the first on ties):
// the study's midpoint rule on 32 x 64 (theta, phi) cells. The study's code compared each
// candidate against sampling direction [theta index] instead of [candidate]; this is the fixed
// search (models/nishita96/README.md, "The binning bug").
struct PhaseIntegrals {
  std::array<double, kSamplingDirections> rayleigh{};
  std::array<double, kSamplingDirections> mie{};
};
PhaseIntegrals binned_phase_integrals(
    Vec3 view, const std::array<Vec3, kSamplingDirections>& sampling_directions, double mie_g,
    int theta_cells = 32);

// The same integrals with the binning done once per sun (it does not depend on the view):
// each bin keeps its directions w and solid angles; the Rayleigh integral of a bin is then
// 3/(16 pi) (Omega_k + v^T M_k v) with M_k = sum of w w^T dOmega (exact, P_R being quadratic),
// and the Cornette-Shanks one a sum over the bin's directions. Immutable; thread-safe.
class PhaseBins {
 public:
  PhaseBins(const std::array<Vec3, kSamplingDirections>& sampling_directions, int theta_cells);
  PhaseIntegrals integrate(Vec3 view, double mie_g) const;

 private:
  std::array<int, kSamplingDirections + 1> begin_{};  // bin k: [begin_[k], begin_[k + 1])
  std::vector<double> x_, y_, z_, solid_angle_;
  std::array<double, kSamplingDirections> bin_solid_angle_{};
  std::array<std::array<double, 6>, kSamplingDirections> moments_{};  // xx, yy, zz, xy, xz, yz
};

}  // namespace clearsky::nishita96
