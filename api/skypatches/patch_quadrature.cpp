// Product Gauss-Legendre rules over sky patches (patch_quadrature.h).
#include "api/skypatches/patch_quadrature.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "models/core/quadrature.h"

namespace clearsky::api {

namespace {

constexpr double kPi = std::numbers::pi;

bool near_sun(const SkyPatchScheme& scheme, std::size_t index, const SkyPatch& patch,
              const PatchQuadratureOrder& order, const std::optional<SunPosition>& sun) {
  if (!sun || sun->zenith_rad >= 0.5 * kPi) return false;
  if (scheme.patch_of(0.5 * kPi - sun->zenith_rad, sun->azimuth_rad) == index + 1) return true;
  const SkyDirection centre{0.5 * kPi - patch.centre_altitude_rad, patch.centre_azimuth_rad};
  return std::acos(cos_angle_between(centre, *sun)) < order.near_sun_rad;
}

}  // namespace

PatchQuadratureOrder default_patch_quadrature_order(const SkyPatchScheme& scheme) {
  PatchQuadratureOrder order;
  order.nodes_per_side = std::max(2, (8 + scheme.subdivision() - 1) / scheme.subdivision());
  order.sun_refinement = 4;
  order.near_sun_rad = 2.0 * scheme.band_height_rad();
  return order;
}

PatchQuadrature patch_quadrature(const SkyPatchScheme& scheme, const PatchQuadratureOrder& order,
                                 const std::optional<SunPosition>& sun) {
  PatchQuadrature q;
  const auto patches = scheme.sky_patches();
  q.first.reserve(patches.size() + 1);
  for (std::size_t i = 0; i < patches.size(); ++i) {
    const SkyPatch& patch = patches[i];
    q.first.push_back(q.views.size());
    const int n =
        order.nodes_per_side * (near_sun(scheme, i, patch, order, sun) ? order.sun_refinement : 1);
    if (patch.cap) {
      // Polar coordinates about the zenith: d Omega = sin(theta) d theta d azimuth.
      const int m = 4 * n;
      const double width = 2.0 * kPi / m;
      for (const auto& [theta, w_theta] :
           gauss_legendre(n, 0.0, 0.5 * kPi - patch.min_altitude_rad)) {
        for (int j = 0; j < m; ++j) {
          q.views.push_back({theta, (j + 0.5) * width});
          q.weights_sr.push_back(w_theta * std::sin(theta) * width);
        }
      }
      continue;
    }
    // d Omega = cos(altitude) d altitude d azimuth.
    const auto altitudes = gauss_legendre(n, patch.min_altitude_rad, patch.max_altitude_rad);
    const auto azimuths = gauss_legendre(n, patch.min_azimuth_rad, patch.max_azimuth_rad);
    for (const auto& [altitude, w_altitude] : altitudes) {
      for (const auto& [phi, w_phi] : azimuths) {
        q.views.push_back({0.5 * kPi - altitude, phi < 0.0 ? phi + 2.0 * kPi : phi});
        q.weights_sr.push_back(w_altitude * std::cos(altitude) * w_phi);
      }
    }
  }
  q.first.push_back(q.views.size());
  return q;
}

}  // namespace clearsky::api
