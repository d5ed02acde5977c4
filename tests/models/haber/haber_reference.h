// Slow reference for the Haber model's scattering terms (docs/conventions.md "Fast paths against
// slow references"): single and double scattering towards a ground viewer by direct numerical
// integration, with the model's own physics (layered densities and transmittance, isotropic
// Rayleigh, Cornette-Shanks for single-scattered Mie, isotropic second scattering, no ground
// albedo) but none of its grid: Gauss-Legendre within each layer along the rays and over the sphere
// of directions.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "models/atmosphere/atmosphere_spectra.h"
#include "models/atmosphere/phase_functions.h"
#include "models/core/quadrature.h"
#include "models/haber/haber_functions.h"

namespace clearsky::haber::testing {

class ScatteringReference {
 public:
  ScatteringReference(const LayeredAtmosphere& layers, const AtmosphereSpectra& atmosphere,
                      double sun_zenith_rad)
      : layers_(layers),
        atmosphere_(atmosphere),
        sun_{std::sin(sun_zenith_rad), 0.0, std::cos(sun_zenith_rad)} {}

  // Single-scattered radiance reaching `origin` from direction `direction` (unit), at each
  // wavelength index of `wavelengths`.
  std::vector<double> single(Vec3 origin, Vec3 direction,
                             const std::vector<std::size_t>& wavelengths,
                             int points_per_layer = 4) const {
    const double mie_phase =
        cornette_shanks_phase(dot(direction, sun_), atmosphere_.parameters.mie_phase_g);
    std::vector<double> sum(wavelengths.size(), 0.0);
    for_each_sample(origin, direction, points_per_layer, [&](Vec3 x, int layer, double weight) {
      const OpticalLength view = optical_length(layers_, origin, x);
      const OpticalLength sun = optical_length(layers_, x, exit_point(layers_, x, sun_));
      if (view.blocked || sun.blocked) return;
      for (std::size_t i = 0; i < wavelengths.size(); ++i) {
        const std::size_t w = wavelengths[i];
        const double scattered =
            atmosphere_.rayleigh_scattering_per_m[w] * layers_.rayleigh_density(layer) *
                isotropic_phase() +
            atmosphere_.mie_scattering_per_m[w] * layers_.mie_density(layer) * mie_phase;
        sum[i] += weight * transmittance(view, w) * transmittance(sun, w) * scattered *
                  atmosphere_.solar_irradiance_w_m2_nm[w];
      }
    });
    return sum;
  }
  double single(Vec3 origin, Vec3 direction, std::size_t w, int points_per_layer = 4) const {
    return single(origin, direction, std::vector<std::size_t>{w}, points_per_layer)[0];
  }

  // Double-scattered radiance reaching the ground viewer from `direction`: the single-scattered
  // radiance integrated over all directions at each point, scattered isotropically.
  std::vector<double> double_scattering(Vec3 direction, const std::vector<std::size_t>& wavelengths,
                                        int zenith_nodes = 16, int azimuth_nodes = 32,
                                        int points_per_layer = 1) const {
    const Vec3 viewer{0.0, 0.0, layers_.earth_radius_m()};
    const auto mu_nodes = gauss_legendre(zenith_nodes, -1.0, 1.0);
    std::vector<double> sum(wavelengths.size(), 0.0);
    for_each_sample(viewer, direction, points_per_layer, [&](Vec3 x, int layer, double weight) {
      std::vector<double> irradiance_over_sphere(wavelengths.size(), 0.0);
      for (const auto& [mu, w_mu] : mu_nodes) {
        const double s = std::sqrt(std::max(0.0, 1.0 - mu * mu));
        for (int j = 0; j < azimuth_nodes; ++j) {
          const double phi = 2.0 * kPi * (j + 0.5) / azimuth_nodes;
          const Vec3 omega{s * std::cos(phi), s * std::sin(phi), mu};
          const auto l1 = single(x, omega, wavelengths, points_per_layer);
          for (std::size_t i = 0; i < l1.size(); ++i)
            irradiance_over_sphere[i] += w_mu * (2.0 * kPi / azimuth_nodes) * l1[i];
        }
      }
      const OpticalLength view = optical_length(layers_, viewer, x);
      for (std::size_t i = 0; i < wavelengths.size(); ++i) {
        const std::size_t w = wavelengths[i];
        const double scattering =
            atmosphere_.rayleigh_scattering_per_m[w] * layers_.rayleigh_density(layer) +
            atmosphere_.mie_scattering_per_m[w] * layers_.mie_density(layer);
        sum[i] += weight * transmittance(view, w) * scattering * isotropic_phase() *
                  irradiance_over_sphere[i];
      }
    });
    return sum;
  }

 private:
  double transmittance(const OpticalLength& l, std::size_t w) const {
    if (l.blocked) return 0.0;
    return std::exp(-(atmosphere_.rayleigh_scattering_per_m[w] * l.rayleigh_m +
                      atmosphere_.mie_extinction_per_m[w] * l.mie_m));
  }

  // Gauss-Legendre samples along the ray from p in direction d up to the top of the layers or
  // the ground, with points_per_layer nodes between successive crossings of layer boundaries.
  template <class F>
  void for_each_sample(Vec3 p, Vec3 d, int points_per_layer, F&& f) const {
    const double top = layers_.earth_radius_m() + layers_.top_height_m() - 1.0;
    const double b = dot(p, d);
    const double c = dot(p, p);
    // End of the ray: the ground when it is hit ahead, else the top.
    double end = -b + std::sqrt(std::max(0.0, b * b - c + top * top));
    const double ground_disc = b * b - c + layers_.earth_radius_m() * layers_.earth_radius_m();
    if (ground_disc > 0.0) {
      const double t_ground = -b - std::sqrt(ground_disc);
      if (t_ground > 1e-6) end = std::min(end, t_ground);
    }
    std::vector<double> breaks{0.0, end};
    for (int i = 1; i < layers_.layer_count(); ++i) {
      const double r = layers_.boundary_radius_m(i);
      const double disc = b * b - c + r * r;
      if (disc <= 0.0) continue;
      for (double t : {-b - std::sqrt(disc), -b + std::sqrt(disc)}) {
        if (t > 0.0 && t < end) breaks.push_back(t);
      }
    }
    // Closest approach to the centre splits a layer too (the height turns back there).
    if (-b > 0.0 && -b < end) breaks.push_back(-b);
    std::sort(breaks.begin(), breaks.end());
    const auto unit = gauss_legendre(points_per_layer, 0.0, 1.0);
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
      const double width = breaks[k + 1] - breaks[k];
      if (!(width > 0.0)) continue;
      for (const auto& [u, weight] : unit) {
        const Vec3 x = p + (breaks[k] + u * width) * d;
        f(x, layers_.layer_index(length(x)), weight * width);
      }
    }
  }

  const LayeredAtmosphere& layers_;
  const AtmosphereSpectra& atmosphere_;
  Vec3 sun_;
};

}  // namespace clearsky::haber::testing
