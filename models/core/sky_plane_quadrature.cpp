// The horizontal and lune quadratures of sky_plane_quadrature.h.
#include "models/core/sky_plane_quadrature.h"

#include <cmath>

#include "models/core/numeric.h"
#include "models/core/quadrature.h"

namespace clearsky {

WeightedDirections sky_plane_quadrature(const PlaneOrientation& plane, int first_nodes,
                                        int second_nodes) {
  WeightedDirections rule;
  const double tilt = plane.tilt_rad;
  if (tilt < 1e-9) {
    for (const auto& [mu, w_mu] : gauss_legendre(first_nodes, 0.0, 1.0)) {
      for (int j = 0; j < second_nodes; ++j) {
        rule.views.push_back({std::acos(mu), 2.0 * kPi * (j + 0.5) / second_nodes});
        rule.weights.push_back(w_mu * mu * 2.0 * kPi / second_nodes);
      }
    }
    return rule;
  }
  if (tilt > kPi - 1e-9) return rule;  // sees only the ground
  const Vec3 z{0, 0, 1};
  const Vec3 n = SkyDirection{tilt, plane.azimuth_rad}.unit_vector();
  const Vec3 a = normalize(cross(z, n));
  const Vec3 v = cross(a, z);
  const auto alpha_nodes = gauss_legendre(first_nodes, 0.0, kPi);
  const auto psi_nodes = gauss_legendre(second_nodes, tilt - 0.5 * kPi, 0.5 * kPi);
  for (const auto& [alpha, w_alpha] : alpha_nodes) {
    const double sin_alpha = std::sin(alpha), cos_alpha = std::cos(alpha);
    for (const auto& [psi, w_psi] : psi_nodes) {
      const Vec3 d = cos_alpha * a + sin_alpha * (std::cos(psi) * z + std::sin(psi) * v);
      rule.views.push_back(SkyDirection::from_unit_vector(d));
      rule.weights.push_back(w_alpha * w_psi * sin_alpha * sin_alpha * std::cos(psi - tilt));
    }
  }
  return rule;
}

Spectrum sky_irradiance_on_plane(std::size_t n_wavelengths, const SkyRadianceBatch& radiance,
                                 const PlaneOrientation& plane, int first_nodes, int second_nodes) {
  const WeightedDirections rule = sky_plane_quadrature(plane, first_nodes, second_nodes);
  Spectrum irradiance(n_wavelengths, 0.0);
  if (rule.views.empty()) return irradiance;
  SpectralBatch batch;
  batch.resize(rule.views.size(), n_wavelengths);
  radiance(rule.views, batch);
  for (std::size_t i = 0; i < rule.views.size(); ++i) {
    if (batch.status[i] != SampleStatus::ok) continue;
    const auto l = batch.spectrum(i);
    for (std::size_t w = 0; w < n_wavelengths; ++w) irradiance[w] += rule.weights[i] * l[w];
  }
  return irradiance;
}

}  // namespace clearsky
