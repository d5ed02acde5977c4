// Reference single-scattering integration (see single_scattering_reference.h).
#include "models/core/single_scattering_reference.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "models/atmosphere/phase_functions.h"
#include "models/core/optical_depth.h"
#include "models/core/quadrature.h"
#include "models/core/ray_sphere.h"

namespace clearsky {

ScatteringAlongRay single_scattering_reference(const AtmosphereSpectra& atmosphere,
                                               const RaySunGeometry& ray, double max_distance_m,
                                               const RayQuadratureOptions& options) {
  const auto& p = atmosphere.parameters;
  const std::size_t n_wavelengths = atmosphere.rayleigh_scattering_per_m.size();
  ScatteringAlongRay result{Spectrum(n_wavelengths, 0.0), Spectrum(n_wavelengths, 1.0), 0.0, false};

  const AtmosphereSegment segment =
      atmosphere_segment(ray.r_m, ray.mu, p.earth_radius_m, p.top_radius_m);
  const double end = std::min(segment.end, max_distance_m);
  if (!(end > segment.start)) return result;
  result.length_m = end - segment.start;
  result.hits_ground = segment.hits_ground && end >= segment.end;

  const std::vector<double> breakpoints =
      ray_breakpoints(ray.r_m, ray.mu, segment.start, end, options.altitude_step_m);
  const auto unit = gauss_legendre(options.nodes_per_piece, 0.0, 1.0);
  auto lengths_between = [&](double a, double b) {
    OpticalLengths lengths;
    for (const auto& [t, w] : unit) {
      const double d = a + (b - a) * t;
      const double altitude = radius_at_distance(ray.r_m, ray.mu, d) - p.earth_radius_m;
      lengths.rayleigh_m += (b - a) * w * std::exp(-altitude / p.rayleigh_scale_height_m);
      lengths.mie_m += (b - a) * w * std::exp(-altitude / p.mie_scale_height_m);
    }
    return lengths;
  };

  std::vector<double> rayleigh_integral(n_wavelengths, 0.0), mie_integral(n_wavelengths, 0.0);
  std::vector<double> t(n_wavelengths);
  OpticalLengths before_piece;  // observer to the start of the current piece
  for (std::size_t piece = 0; piece + 1 < breakpoints.size(); ++piece) {
    const double a = breakpoints[piece], b = breakpoints[piece + 1];
    for (const auto& [u, w] : unit) {
      const double d = a + (b - a) * u;
      const double radius = radius_at_distance(ray.r_m, ray.mu, d);
      const auto to_sun =
          optical_lengths_to_space(atmosphere, radius, ray.mu_s_at(d, radius), options);
      if (!to_sun) continue;  // in the Earth's shadow
      OpticalLengths total = before_piece;
      total += lengths_between(a, d);
      total += *to_sun;
      transmittance_into(atmosphere, total, t.data());
      const double altitude = radius - p.earth_radius_m;
      const double weight_rayleigh = (b - a) * w * std::exp(-altitude / p.rayleigh_scale_height_m);
      const double weight_mie = (b - a) * w * std::exp(-altitude / p.mie_scale_height_m);
      for (std::size_t i = 0; i < n_wavelengths; ++i) {
        rayleigh_integral[i] += weight_rayleigh * t[i];
        mie_integral[i] += weight_mie * t[i];
      }
    }
    before_piece += lengths_between(a, b);
  }

  const double phase_rayleigh = rayleigh_phase(ray.nu);
  const double phase_mie = cornette_shanks_phase(ray.nu, p.mie_phase_g);
  for (std::size_t i = 0; i < n_wavelengths; ++i) {
    result.radiance[i] =
        atmosphere.solar_irradiance_w_m2_nm[i] *
        (atmosphere.rayleigh_scattering_per_m[i] * phase_rayleigh * rayleigh_integral[i] +
         atmosphere.mie_scattering_per_m[i] * phase_mie * mie_integral[i]);
  }
  result.transmittance = transmittance(atmosphere, before_piece);
  return result;
}

}  // namespace clearsky
