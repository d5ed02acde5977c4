// Numerical optical lengths for exponential profiles (see optical_depth.h).
#include "models/core/optical_depth.h"

#include <cmath>

#include "models/core/ray_sphere.h"

namespace clearsky {

namespace {

OpticalLengths integrate_lengths(double r, double mu, double d0, double d1, double bottom,
                                 double h_rayleigh, double h_mie,
                                 const RayQuadratureOptions& options) {
  OpticalLengths lengths;
  for (const RayNode& node : ray_nodes(ray_breakpoints(r, mu, d0, d1, options.altitude_step_m),
                                       options.nodes_per_piece)) {
    const double altitude = radius_at_distance(r, mu, node.distance_m) - bottom;
    lengths.rayleigh_m += node.weight_m * std::exp(-altitude / h_rayleigh);
    lengths.mie_m += node.weight_m * std::exp(-altitude / h_mie);
  }
  return lengths;
}

}  // namespace

double exponential_optical_length_m(double r_m, double mu, double distance_m,
                                    double bottom_radius_m, double scale_height_m,
                                    const RayQuadratureOptions& options) {
  double length = 0.0;
  for (const RayNode& node :
       ray_nodes(ray_breakpoints(r_m, mu, 0.0, distance_m, options.altitude_step_m),
                 options.nodes_per_piece)) {
    const double altitude = radius_at_distance(r_m, mu, node.distance_m) - bottom_radius_m;
    length += node.weight_m * std::exp(-altitude / scale_height_m);
  }
  return length;
}

double vertical_optical_length_m(double h0_m, double h1_m, double scale_height_m) {
  return scale_height_m * (std::exp(-h0_m / scale_height_m) - std::exp(-h1_m / scale_height_m));
}

OpticalLengths optical_lengths(const AtmosphereSpectra& atmosphere, double r_m, double mu,
                               double distance_m, const RayQuadratureOptions& options) {
  const auto& p = atmosphere.parameters;
  return integrate_lengths(r_m, mu, 0.0, distance_m, p.earth_radius_m, p.rayleigh_scale_height_m,
                           p.mie_scale_height_m, options);
}

bool ray_hits_ground(double r_m, double mu, double bottom_radius_m) {
  return ray_hits_sphere_from_outside(std::max(r_m, bottom_radius_m), mu, bottom_radius_m);
}

std::optional<OpticalLengths> optical_lengths_to_space(const AtmosphereSpectra& atmosphere,
                                                       double r_m, double mu,
                                                       const RayQuadratureOptions& options) {
  const auto& p = atmosphere.parameters;
  if (ray_hits_ground(r_m, mu, p.earth_radius_m)) return std::nullopt;
  const AtmosphereSegment segment = atmosphere_segment(r_m, mu, p.earth_radius_m, p.top_radius_m);
  return integrate_lengths(r_m, mu, segment.start, segment.end, p.earth_radius_m,
                           p.rayleigh_scale_height_m, p.mie_scale_height_m, options);
}

void transmittance_into(const AtmosphereSpectra& atmosphere, const OpticalLengths& lengths,
                        double* out) {
  const std::size_t n = atmosphere.rayleigh_scattering_per_m.size();
  const double* rayleigh = atmosphere.rayleigh_scattering_per_m.data();
  const double* mie = atmosphere.mie_extinction_per_m.data();
  for (std::size_t i = 0; i < n; ++i)
    out[i] = std::exp(-(rayleigh[i] * lengths.rayleigh_m + mie[i] * lengths.mie_m));
}

Spectrum transmittance(const AtmosphereSpectra& atmosphere, const OpticalLengths& lengths) {
  Spectrum t(atmosphere.rayleigh_scattering_per_m.size());
  transmittance_into(atmosphere, lengths, t.data());
  return t;
}

Spectrum transmittance_to_space(const AtmosphereSpectra& atmosphere, double r_m, double mu,
                                const RayQuadratureOptions& options) {
  const auto lengths = optical_lengths_to_space(atmosphere, r_m, mu, options);
  if (!lengths) return Spectrum(atmosphere.rayleigh_scattering_per_m.size(), 0.0);
  return transmittance(atmosphere, *lengths);
}

}  // namespace clearsky
