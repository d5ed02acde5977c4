// Nishita93's precomputation (Nishita et al. 1993, section 4; paper section "Nishita93 Model",
// models/nishita93/README.md): the atmosphere is cut by n_s spheres of equal steps of
// Rayleigh density (layers of equal Rayleigh optical depth), ground to top,
//   r_i = R - H_R ln(1 + a i / (n_s - 1)),   a = exp(-(R_top - R) / H_R) - 1,
// and by n_c cylinders of radii R_top j / (n_c - 1) whose axis points at the sun. At the
// intersection of sphere i and cylinder j, the optical lengths (integrals of relative Rayleigh
// and Mie density, m) towards the sun are stored, for the sun along the cylinder axis (the
// point on the sun side) and against it (the far side): 4 tables of n_s x n_c, each integrated
// with the trapezoid rule over the ray's crossings of the same spheres.
//
// The 2D table does not depend on the sun: a point at radius r whose sun zenith cosine is
// mu_s lies on sphere coordinate x = (exp(-(r - R)/H_R) - 1) / a and cylinder radius
// r sqrt(1 - mu_s^2); lookups are bilinear between the nodes (the study's texel-centre lookup
// of an n_s x n_c texture at (0.5 + (n_s - 1) x) / n_s is exactly this).
//
// Beyond the study: the against-axis tables follow the ray through its tangent point (the
// study's code reused the near intersections on the way up, a defect it never exercised with
// the sun above the horizon), but no lookup reads them any more (sun_optical_lengths: they do
// not converge in the cylinder count; node() still reports them); rays that meet the ground are shadowed (lookups report it), and
// their table entries hold the ground-grazing chord so that bilinear lookups next to the
// shadow stay monotone. Immutable after build(); thread-safe.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "models/atmosphere/atmosphere_parameters.h"
#include "models/core/numeric.h"
#include "models/core/optical_depth.h"
#include "models/core/precompute_context.h"

namespace clearsky {

class Nishita93Tables {
 public:
  // spheres, cylinders >= 2 (the study: 64 and 64). May throw PrecomputeCancelled.
  static Nishita93Tables build(const AtmosphereParameters& atmosphere, int spheres, int cylinders,
                               const PrecomputeContext& context = {});
  // memory_bytes() of the tables build() makes with these counts, without building them.
  static std::size_t memory_bytes_for(int spheres, int cylinders);
  // The radii of the n_s spheres build() cuts the atmosphere with (equal steps of Rayleigh
  // density, the first on the ground and the last at the top), without building the tables: the
  // view-ray samples of Nishita93 and Nishita96 are their crossings.
  static std::vector<double> sphere_radii_m(const AtmosphereParameters& atmosphere, int spheres);

  int sphere_count() const { return sphere_count_; }
  int cylinder_count() const { return cylinder_count_; }
  double sphere_radius_m(int i) const { return sphere_radius_m_[static_cast<std::size_t>(i)]; }
  const std::vector<double>& sphere_radii_m() const { return sphere_radius_m_; }
  double sphere_rayleigh_density(int i) const {
    return sphere_rayleigh_density_[static_cast<std::size_t>(i)];
  }
  double sphere_mie_density(int i) const {
    return sphere_mie_density_[static_cast<std::size_t>(i)];
  }
  double bottom_radius_m() const { return bottom_radius_m_; }
  double top_radius_m() const { return top_radius_m_; }

  // Optical lengths from a point at radius r_m (any radius >= the ground) to the sun, whose
  // zenith cosine there is mu_s; nothing when the Earth hides the sun. sphere_index >= 0 says
  // the point lies on that sphere (saves the density coordinate's exp).
  std::optional<OpticalLengths> sun_optical_lengths(double r_m, double mu_s,
                                                    int sphere_index = -1) const;
  // sun_optical_lengths(sphere_radius_m(k), mu_s, k) for the sun above the point's horizon
  // (mu_s >= 0), where it always has lengths: the same operations on the same values without
  // the general case's tests, inline for the view-ray samples of Nishita93, which lie on the
  // spheres.
  OpticalLengths sun_optical_lengths_on_sphere(int k, double mu_s) const {
    return along_row(k, safe_sqrt(1.0 - mu_s * mu_s), std::abs(mu_s));
  }

  // Raw node values (tests): optical lengths stored at sphere i, cylinder j.
  OpticalLengths node(int i, int j, bool against_axis) const;

  std::size_t memory_bytes() const;

 private:
  // Bilinear lookup of both along-axis tables at sphere coordinate u, each sphere read at the
  // sun zenith angle of sine sin_s (and |cos| abs_mu_s).
  OpticalLengths along_lookup(double u, double sin_s, double abs_mu_s) const;
  // The horizontal ray's optical lengths at radius r_m (between the ground and the top).
  OpticalLengths horizontal_lengths(double r_m) const;
  // Both along-axis tables on sphere k, linear in the cylinder radius (below the class).
  OpticalLengths along_row(int k, double sin_s, double abs_mu_s) const;

  int sphere_count_ = 0, cylinder_count_ = 0;
  double bottom_radius_m_ = 0, top_radius_m_ = 0, rayleigh_scale_height_m_ = 0;
  double density_step_ = 0;  // a of the sphere radii formula
  std::vector<double> sphere_radius_m_, sphere_rayleigh_density_, sphere_mie_density_;
  // Per sphere: the last cylinder inside it and that cylinder's sun zenith cosine there.
  std::vector<int> last_inner_cylinder_;
  std::vector<double> last_inner_cylinder_mu_;
  // [i * cylinder_count + j]
  std::vector<double> along_rayleigh_m_, along_mie_m_, against_rayleigh_m_, against_mie_m_;
};

inline OpticalLengths Nishita93Tables::along_row(int k, double sin_s, double abs_mu_s) const {
  const double r_k = sphere_radius_m_[static_cast<std::size_t>(k)];
  const double max_v = cylinder_count_ - 1.0;
  const std::size_t row = static_cast<std::size_t>(k) * static_cast<std::size_t>(cylinder_count_);
  const double v = std::clamp(max_v * r_k * sin_s / top_radius_m_, 0.0, max_v);
  // The last cylinder inside this sphere: beyond it, up to the sphere itself (the sun on the
  // horizon), the lengths change like the square root of the distance to the sphere, which a
  // linear interpolation in the cylinder radius towards the next cylinder (outside the sphere,
  // where the table holds the horizontal ray) cannot follow. There they are interpolated
  // linearly in |mu_s| (the optical length of a ray is smooth in its zenith cosine through the
  // horizon) between that cylinder and the horizontal ray, so that they reach the horizontal
  // ray's at mu_s = 0, where the sun below the horizon (sun_optical_lengths) starts from.
  const int last = last_inner_cylinder_[static_cast<std::size_t>(k)];
  if (v > last) {
    const std::size_t horizontal = row + static_cast<std::size_t>(cylinder_count_ - 1);
    const std::size_t inner = row + static_cast<std::size_t>(last);
    const double mu_last = last_inner_cylinder_mu_[static_cast<std::size_t>(k)];
    const double t = mu_last > 0.0 ? std::min(abs_mu_s / mu_last, 1.0) : 0.0;
    return {t * along_rayleigh_m_[inner] + (1.0 - t) * along_rayleigh_m_[horizontal],
            t * along_mie_m_[inner] + (1.0 - t) * along_mie_m_[horizontal]};
  }
  const int j = std::min(static_cast<int>(v), cylinder_count_ - 2);
  const double fv = v - j;
  const std::size_t cell = row + static_cast<std::size_t>(j);
  return {(1.0 - fv) * along_rayleigh_m_[cell] + fv * along_rayleigh_m_[cell + 1],
          (1.0 - fv) * along_mie_m_[cell] + fv * along_mie_m_[cell + 1]};
}

}  // namespace clearsky
