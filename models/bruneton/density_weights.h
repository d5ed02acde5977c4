// The scalar weights of the density J (Bruneton and Neyret 2008, Eq. 7; the 2008 code's
// inscatterS), the costly half of the precomputation (docs/performance.md "Bruneton's
// precomputation").
//
// At a texel (r, mu, mu_s, nu) J sums, over the 16 x 32 directions w of the sphere, the light
// arriving from w (a lookup at (r, w.z, mu_s, s.w), linear in the two nu slices around s.w)
// times the phase of its scattering towards the view, plus the light the ground seen in w
// reflects. The light itself is wavelength-dependent but the weights are geometry: each
// direction adds (1 - f) and f times its phase to its zenith's two nu slices, and its share to
// the irradiance table's columns at the ground point's sun cosine. The precomputation then sums
// its spectra with these weights (bruneton_tables.cpp).
//
// The weights are computed for the texels of one layer, view row and sun cosine at once (the
// table's nu slices: only their sun direction (sx, sy) in the view's frame differs, the phases
// and the ground do not). Each weight is the same sum of the same terms in the same order as
// one texel at a time (the reference below, the code of before), so the tables are the same bit
// for bit (tests/models/bruneton/density_weights_test.cpp); the AVX2 path computes four texels'
// directions in one vector pass.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "models/bruneton/bruneton_functions.h"
#include "models/bruneton/bruneton_tables.h"

namespace clearsky::bruneton {

// What the texels of one layer, view row and sun cosine share.
struct DensitySphere {
  int n_theta = 0;                // zeniths of the sphere
  int n_phi = 0;                  // azimuths per zenith
  int n_nu = 0;                   // nu slices of the lookups
  int n_e = 0;                    // columns of the irradiance table's ground row
  const double* cos_t = nullptr;  // n_theta zenith cosines
  const double* wx = nullptr;     // per direction i * n_phi + p: its x and y in the view's frame
  const double* wy = nullptr;
  const double* phase_r = nullptr;   // per direction: Rayleigh phase towards the view x solid angle
  const double* phase_m = nullptr;   // per direction: Mie phase towards the view x solid angle
  const char* ground = nullptr;      // n_theta: whether zenith i sees the ground
  const double* d_ground = nullptr;  // n_theta: the distance to that ground
  double r = 0;                      // the layer's radius, m
  double mu_s = 0;                   // the sun's zenith cosine
  double bottom_m = 0;               // the ground's radius, m
  SunRange sun;                      // the irradiance table's mu_s axis
  const MiePhase* mie_phase = nullptr;
  bool first = false;  // the source is single scattering: its phases are applied here (b_*)
};

// The weights of `texels` texels. Profile weights of texel t at zenith i and nu slice k, next
// to each other in `profile` (so that a direction adds its share to a slot in one vector
// operation): a_r, a_m (the profile a times the Rayleigh / Mie phase towards the view) and, for
// the first order, b_r, b_m (profile b); slot n_nu of each zenith is scratch. Ground column
// weights g_r, g_m, next to each other in `ground`: zero outside ground_range (lowest, highest
// column touched at zenith i, highest < lowest for none); whoever reads them sets them back to
// zero (clear_column).
struct DensityWeights {
  int texels = 0, n_theta = 0, n_nu = 0, n_e = 0;
  int per_slot = 2;  // weights per profile slot: 2, or 4 for the first order
  std::vector<double> profile, ground;
  std::vector<std::pair<int, int>> ground_range;

  // Sizes the arrays for `texels` texels (room for a multiple of 4) and zeroes the profile
  // weights; the ground weights are zero already (or set so when allocated).
  void prepare(int texel_count, const DensitySphere& sphere);
  std::size_t slot(int t, int i, int k) const {
    return (static_cast<std::size_t>(t) * n_theta + i) * (n_nu + 1) + k;
  }
  std::size_t column(int t, int i, int c) const {
    return (static_cast<std::size_t>(t) * n_theta + i) * n_e + c;
  }
  std::pair<int, int>& range(int t, int i) {
    return ground_range[static_cast<std::size_t>(t) * n_theta + i];
  }
  double a_r(std::size_t slot) const { return profile[slot * per_slot]; }
  double a_m(std::size_t slot) const { return profile[slot * per_slot + 1]; }
  double b_r(std::size_t slot) const { return profile[slot * per_slot + 2]; }
  double b_m(std::size_t slot) const { return profile[slot * per_slot + 3]; }
  double g_r(std::size_t column) const { return ground[2 * column]; }
  double g_m(std::size_t column) const { return ground[2 * column + 1]; }
  void clear_column(std::size_t column) {
    ground[2 * column] = 0.0;
    ground[2 * column + 1] = 0.0;
  }
};

// The weights of texels t in [0, texels) whose sun direction in the view's frame is
// (sx[t], sy[t], mu_s); sx and sy hold a multiple of 4 values (the extra ones any finite
// values). `weights` must have been prepared for these texels.
void density_weights(const DensitySphere& sphere, const double* sx, const double* sy, int texels,
                     DensityWeights& weights);

// The same one texel at a time, as the precomputation did before: the path of CPUs without
// AVX2, and the reference of the tests.
void density_weights_reference(const DensitySphere& sphere, const double* sx, const double* sy,
                               int texels, DensityWeights& weights);

}  // namespace clearsky::bruneton
