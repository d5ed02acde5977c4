// Nishita93's view-ray integration over the sphere crossings (see nishita93_functions.h).
#include "models/nishita93/nishita93_functions.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "models/atmosphere/phase_functions.h"
#include "models/core/ray_sphere.h"
#include "models/core/weighted_transmittance_sums.h"

namespace clearsky::nishita93 {

namespace {

// Calls emit(distance, sphere index or -1) for the samples of the segment [start, end] of the
// ray (r, mu), in increasing distance: start, the sphere crossings strictly inside, the
// tangent point if the segment passes it without meeting the ground, and end.
template <typename Emit>
void for_each_sample(const Nishita93Tables& tables, double r, double mu, double start, double end,
                     int start_sphere, int end_sphere, Emit&& emit) {
  const std::vector<double>& radius = tables.sphere_radii_m();
  const int n = tables.sphere_count();
  emit(start, start_sphere);
  // The sphere the segment starts on (the observer's, or the top for an observer above the
  // atmosphere): its crossing next to the start is the start sample itself, computed again with
  // rounding (a few 1e-10 m away, on either side); emitting it too would make a second sample
  // at the observer.
  const double start_radius =
      start_sphere >= 0 ? radius[static_cast<std::size_t>(start_sphere)] : r;
  const double rmu = r * mu;
  const double c2 = r * r - rmu * rmu;  // squared distance of the ray's line to the centre
  const double tangent = -rmu;
  auto crossing = [&](int k, double sign) {
    const double rk = radius[static_cast<std::size_t>(k)];
    return tangent + sign * safe_sqrt(rk * rk - c2);
  };
  int lowest = 0;  // lowest sphere the line crosses
  while (lowest < n &&
         radius[static_cast<std::size_t>(lowest)] * radius[static_cast<std::size_t>(lowest)] <=
             c2) {
    ++lowest;
  }
  if (tangent > start) {
    // Going down: near crossings of the spheres below the start, highest first.
    const double r_start = radius_at_distance(r, mu, start);
    int k =
        static_cast<int>(std::lower_bound(radius.begin(), radius.end(), r_start) - radius.begin()) -
        1;
    for (; k >= lowest; --k) {
      const double d = crossing(k, -1.0);
      if (d >= end) break;
      if (d > start && radius[static_cast<std::size_t>(k)] != start_radius) emit(d, k);
    }
    if (k >= lowest || lowest == 0) {  // the segment ended first, or the ray meets the ground
      emit(end, end_sphere);
      return;
    }
    if (tangent < end) emit(tangent, -1);
  }
  // Going up: far crossings, lowest first.
  for (int k = lowest; k < n; ++k) {
    const double d = crossing(k, 1.0);
    if (d >= end) break;
    if (d > start && d > tangent && radius[static_cast<std::size_t>(k)] != start_radius) emit(d, k);
  }
  emit(end, end_sphere);
}

}  // namespace

void sun_transmittance(const Nishita93Tables& tables, const AtmosphereSpectra& atmosphere,
                       double r_m, double mu_s, std::span<double> out) {
  const auto lengths = tables.sun_optical_lengths(r_m, mu_s);
  if (!lengths) {
    std::fill(out.begin(), out.end(), 0.0);
    return;
  }
  transmittance_into(atmosphere, *lengths, out.data());
}

bool single_scattering(const Nishita93Tables& tables, const AtmosphereSpectra& atmosphere,
                       const RaySunGeometry& ray, double max_distance_m,
                       std::span<double> radiance_out, std::span<double> transmittance_out,
                       const RayWorkspace& workspace, bool study_viewer_sample,
                       TransmittanceKernel kernel) {
  const auto& p = atmosphere.parameters;
  const std::size_t n_wavelengths = radiance_out.size();
  std::fill(radiance_out.begin(), radiance_out.end(), 0.0);
  std::fill(transmittance_out.begin(), transmittance_out.end(), 1.0);
  const AtmosphereSegment segment =
      atmosphere_segment(ray.r_m, ray.mu, p.earth_radius_m, p.top_radius_m);
  const bool limited = max_distance_m < segment.end;
  const double end = std::min(segment.end, max_distance_m);
  if (!(end > segment.start)) return false;

  const int top_sphere = tables.sphere_count() - 1;
  const int start_sphere = segment.start > 0.0 ? top_sphere : -1;
  const int end_sphere = limited ? -1 : segment.hits_ground ? 0 : top_sphere;

  const double* beta_rayleigh = atmosphere.rayleigh_scattering_per_m.data();
  double* rayleigh_integral = workspace.rayleigh_integral.data();
  double* mie_integral = workspace.mie_integral.data();
  // The samples' transmittances and weights go to the integrals in vector passes over chunks
  // of samples.
  WeightedTransmittanceSums sums(n_wavelengths, beta_rayleigh,
                                 atmosphere.mie_extinction_per_m.data(), rayleigh_integral,
                                 mie_integral, kernel);

  // The trapezoid rule over the samples, for the observer-side optical lengths and for the
  // integrands rho_p T. A sample's weight is half the sum of its two neighbouring segments, so
  // it is added to the integrals when the next sample is known (`pending`). A sample in the
  // Earth's shadow (or the observer's with study_viewer_sample) has T = 0 and adds nothing.
  double previous_d = 0.0, previous_rho_r = 0.0, previous_rho_m = 0.0, pending_half_before = 0.0;
  bool first = true, pending_lit = false;
  OpticalLengths view, pending_lengths;
  auto add_sample = [&](double d, int sphere) {
    double radius, rho_r, rho_m;
    if (sphere >= 0) {
      radius = tables.sphere_radius_m(sphere);
      rho_r = tables.sphere_rayleigh_density(sphere);
      rho_m = tables.sphere_mie_density(sphere);
    } else {
      radius = std::max(radius_at_distance(ray.r_m, ray.mu, d), p.earth_radius_m);
      rho_r = std::exp(-(radius - p.earth_radius_m) / p.rayleigh_scale_height_m);
      rho_m = std::exp(-(radius - p.earth_radius_m) / p.mie_scale_height_m);
    }
    const double half = first ? 0.0 : 0.5 * (d - previous_d);
    if (!first && pending_lit) {
      const double weight = pending_half_before + half;
      sums.add(pending_lengths.rayleigh_m, pending_lengths.mie_m, weight * previous_rho_r,
               weight * previous_rho_m);
    }
    view.rayleigh_m += half * (rho_r + previous_rho_r);
    view.mie_m += half * (rho_m + previous_rho_m);
    const double mu_s = ray.mu_s_at(d, radius);
    const std::optional<OpticalLengths> sun =
        sphere >= 0 && mu_s >= 0.0 ? tables.sun_optical_lengths_on_sphere(sphere, mu_s)
                                   : tables.sun_optical_lengths(radius, mu_s, sphere);
    pending_lit = sun && !(first && study_viewer_sample);
    if (pending_lit) {
      pending_lengths = {view.rayleigh_m + sun->rayleigh_m, view.mie_m + sun->mie_m};
    }
    pending_half_before = half;
    previous_d = d;
    previous_rho_r = rho_r;
    previous_rho_m = rho_m;
    first = false;
  };
  for_each_sample(tables, ray.r_m, ray.mu, segment.start, end, start_sphere, end_sphere,
                  add_sample);
  if (pending_lit) {
    sums.add(pending_lengths.rayleigh_m, pending_lengths.mie_m,
             pending_half_before * previous_rho_r, pending_half_before * previous_rho_m);
  }
  sums.flush();

  const double phase_rayleigh = rayleigh_phase(ray.nu);
  const double phase_mie = cornette_shanks_phase(ray.nu, p.mie_phase_g);
  const double* beta_mie_scattering = atmosphere.mie_scattering_per_m.data();
  const double* solar = atmosphere.solar_irradiance_w_m2_nm.data();
  for (std::size_t w = 0; w < n_wavelengths; ++w) {
    radiance_out[w] = solar[w] * (beta_rayleigh[w] * phase_rayleigh * rayleigh_integral[w] +
                                  beta_mie_scattering[w] * phase_mie * mie_integral[w]);
  }
  if (!transmittance_out.empty()) transmittance_into(atmosphere, view, transmittance_out.data());
  return segment.hits_ground && !limited;
}

}  // namespace clearsky::nishita93

namespace clearsky::nishita93 {

ScatteringAlongRay single_scattering(const Nishita93Tables& tables,
                                     const AtmosphereSpectra& atmosphere, const RaySunGeometry& ray,
                                     double max_distance_m, bool study_viewer_sample,
                                     TransmittanceKernel kernel) {
  const std::size_t n = atmosphere.rayleigh_scattering_per_m.size();
  std::vector<double> scratch(2 * n);
  const std::span<double> all(scratch);
  const RayWorkspace workspace{all.subspan(0, n), all.subspan(n, n)};
  ScatteringAlongRay result{Spectrum(n), Spectrum(n), 0.0, false};
  result.hits_ground =
      single_scattering(tables, atmosphere, ray, max_distance_m, {result.radiance.data(), n},
                        {result.transmittance.data(), n}, workspace, study_viewer_sample, kernel);
  const auto& p = atmosphere.parameters;
  const AtmosphereSegment segment =
      atmosphere_segment(ray.r_m, ray.mu, p.earth_radius_m, p.top_radius_m);
  result.length_m = std::max(0.0, std::min(segment.end, max_distance_m) - segment.start);
  return result;
}

}  // namespace clearsky::nishita93
