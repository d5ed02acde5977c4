// Pure physics of the Haber model as the 2016 study implemented it (paper section "Haber
// Model", "Our implementation"; models/haber/README.md): the atmosphere is cut into
// layers of equal Rayleigh mass up to 35 km, each of constant density (the density at the
// layer's middle height), and transmittances are computed exactly through these layers.
// Transmittance uses Rayleigh scattering plus Mie extinction (no absorber).
//
// Frame: origin at the centre of the Earth, viewer at (0, 0, R), z up, x towards the sun's
// azimuth (the sun is at (sin sz, 0, cos sz)). Lengths in metres.
#pragma once

#include <vector>

#include "models/core/geometry.h"

namespace clearsky::haber {

// Layers of equal Rayleigh mass: boundary i at height -H ln(1 - i M), M = (1 - exp(-top/H)) /
// count, so that each layer holds 1/count of the Rayleigh column below `top`.
class LayeredAtmosphere {
 public:
  LayeredAtmosphere(double earth_radius_m, double top_height_m, int layer_count,
                    double rayleigh_scale_height_m, double mie_scale_height_m);

  int layer_count() const { return layer_count_; }
  double earth_radius_m() const { return earth_radius_m_; }
  double top_height_m() const { return top_height_m_; }
  // Height of boundary i in [0, layer_count] (boundary 0 is the ground).
  double boundary_height_m(int i) const;
  // Distance of boundary i from the Earth's centre.
  double boundary_radius_m(int i) const { return boundary_radius_m_[i]; }
  // Index of the layer holding a point at this distance from the Earth's centre, clamped to
  // [0, layer_count - 1] (points rounded just below the ground or above the top).
  int layer_index(double radius_m) const;
  double rayleigh_density(int layer) const { return rayleigh_density_[layer]; }
  double mie_density(int layer) const { return mie_density_[layer]; }

 private:
  double earth_radius_m_;
  double top_height_m_;
  int layer_count_;
  double rayleigh_scale_height_m_;
  double mass_step_;  // M above
  std::vector<double> boundary_radius_m_;
  std::vector<double> rayleigh_density_;
  std::vector<double> mie_density_;
};

// Density-weighted lengths along a segment (metres at sea-level density): the optical depth is
// rayleigh_m * sigma_R + mie_m * sigma_M,ext.
struct OpticalLength {
  double rayleigh_m = 0;
  double mie_m = 0;
  bool blocked = false;  // the segment passes below the ground: transmittance 0
};

// Optical length of the segment [p, q], both inside the layered atmosphere. A segment whose
// closest point to the Earth's centre lies strictly between p and q is split there, so that
// each part crosses every layer at most once; a segment that passes below the ground is
// blocked.
OpticalLength optical_length(const LayeredAtmosphere& layers, Vec3 p, Vec3 q);

// Where a ray from p towards `direction` (unit) leaves the layered atmosphere: the study takes
// the sphere 1 m below the top so that the end point lies in the last layer.
Vec3 exit_point(const LayeredAtmosphere& layers, Vec3 p, Vec3 direction);

}  // namespace clearsky::haber
