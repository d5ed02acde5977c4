// O'Neal's single scattering with Schuler's Chapman approximation (see oneal_functions.h).
#include "models/oneal/oneal_functions.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "models/atmosphere/phase_functions.h"
#include "models/core/ray_sphere.h"
#include "models/core/weighted_transmittance_sums.h"

namespace clearsky::oneal {

namespace {

struct Point {
  double radius;
  double mu;  // view zenith cosine at the point
};

// Schuler's scale function of one profile with its constants c = sqrt(R / H) and H c computed
// once per ray instead of once per length (four lengths per sample): the same expression as
// scale_m(), so the same values.
struct Profile {
  double h, c, hc;
  Profile(double scale_height_m, double bottom_radius_m)
      : h(scale_height_m), c(std::sqrt(bottom_radius_m / scale_height_m)), hc(scale_height_m * c) {}
  double scale(double mu) const { return hc / (c * std::max(mu, 0.0) + 1.0); }
};

// The two profiles of the atmosphere above the ground radius.
struct Profiles {
  Profile rayleigh, mie;
  double bottom;
  explicit Profiles(const AtmosphereParameters& p)
      : rayleigh(p.rayleigh_scale_height_m, p.earth_radius_m),
        mie(p.mie_scale_height_m, p.earth_radius_m),
        bottom(p.earth_radius_m) {}
};

// Relative density exp(-(r - bottom) / h) of one profile at radius r.
double density(double r, double h, double bottom) { return std::exp(-(r - bottom) / h); }

// Optical length of one profile to infinity along mu (any sign; the caller has excluded rays
// that meet the ground), with rho = density(r, h, bottom) computed by the caller, who uses it
// for more than one length.
double length_to_infinity(double r, double mu, const Profile& profile, double bottom, double rho) {
  if (mu >= 0.0) return rho * profile.scale(mu);
  const double tangent_radius = r * safe_sqrt(1.0 - mu * mu);
  return 2.0 * std::exp(-(tangent_radius - bottom) / profile.h) * profile.scale(0.0) -
         rho * profile.scale(-mu);
}

// The Rayleigh and Mie relative densities at a radius.
OpticalLengths densities(const Profiles& p, double r) {
  return {density(r, p.rayleigh.h, p.bottom), density(r, p.mie.h, p.bottom)};
}

OpticalLengths lengths_to_infinity(const Profiles& p, double r, double mu,
                                   const OpticalLengths& rho) {
  return {length_to_infinity(r, mu, p.rayleigh, p.bottom, rho.rayleigh_m),
          length_to_infinity(r, mu, p.mie, p.bottom, rho.mie_m)};
}

// Optical lengths to infinity of a point of the view: along the view when it escapes, along
// the reversed view (upward through the point) when it meets the ground.
OpticalLengths view_lengths_to_infinity(const Profiles& p, const Point& a, bool view_hits_ground,
                                        const OpticalLengths& rho) {
  return lengths_to_infinity(p, a.radius, view_hits_ground ? -a.mu : a.mu, rho);
}

// Optical lengths between two points of the view, from the observer-side one (a) to b, as
// differences of their lengths to infinity (view_lengths_to_infinity).
OpticalLengths lengths_between(const OpticalLengths& la, const OpticalLengths& lb,
                               bool view_hits_ground) {
  const double sign = view_hits_ground ? -1.0 : 1.0;
  return {std::max(0.0, sign * (la.rayleigh_m - lb.rayleigh_m)),
          std::max(0.0, sign * (la.mie_m - lb.mie_m))};
}

}  // namespace

double scale_m(double scale_height_m, double bottom_radius_m, double mu) {
  const double c = std::sqrt(bottom_radius_m / scale_height_m);
  return scale_height_m * c / (c * std::max(mu, 0.0) + 1.0);
}

std::optional<OpticalLengths> optical_lengths_to_infinity(const AtmosphereParameters& atmosphere,
                                                          double r_m, double mu) {
  if (ray_hits_ground(r_m, mu, atmosphere.earth_radius_m)) return std::nullopt;
  const Profiles profiles(atmosphere);
  const double r = std::max(r_m, atmosphere.earth_radius_m);
  return lengths_to_infinity(profiles, r, mu, densities(profiles, r));
}

bool single_scattering(const AtmosphereSpectra& atmosphere, const RaySunGeometry& ray, int samples,
                       double max_distance_m, std::span<double> radiance_out,
                       std::span<double> transmittance_out, const RayWorkspace& workspace,
                       TransmittanceKernel kernel) {
  const auto& p = atmosphere.parameters;
  const std::size_t n_wavelengths = radiance_out.size();
  std::fill(radiance_out.begin(), radiance_out.end(), 0.0);
  std::fill(transmittance_out.begin(), transmittance_out.end(), 1.0);
  const AtmosphereSegment segment =
      atmosphere_segment(ray.r_m, ray.mu, p.earth_radius_m, p.top_radius_m);
  const double end = std::min(segment.end, max_distance_m);
  if (!(end > segment.start) || samples < 1) return false;
  // Whether the whole line of the view meets the ground (then lengths go along the reversed ray).
  const bool line_hits_ground = segment.hits_ground;
  const Profiles profiles(p);

  // The radius and the view zenith cosine at distance d (mu_at_distance from the same radius,
  // computed once).
  auto point_at = [&](double d) {
    const double r_d = radius_at_distance(ray.r_m, ray.mu, d);
    return Point{std::max(r_d, p.earth_radius_m),
                 r_d > 0.0 ? clamp_cosine((ray.r_m * ray.mu + d) / r_d) : 1.0};
  };
  const Point start = point_at(segment.start);
  const double sample_length = (end - segment.start) / samples;
  // The observer-side end's lengths to infinity, once for all samples.
  const OpticalLengths start_lengths = view_lengths_to_infinity(profiles, start, line_hits_ground,
                                                                densities(profiles, start.radius));

  const double* beta_rayleigh = atmosphere.rayleigh_scattering_per_m.data();
  double* rayleigh_integral = workspace.rayleigh_integral.data();
  double* mie_integral = workspace.mie_integral.data();
  // The samples' transmittances and weights go to the integrals in one vector pass.
  WeightedTransmittanceSums sums(n_wavelengths, beta_rayleigh,
                                 atmosphere.mie_extinction_per_m.data(), rayleigh_integral,
                                 mie_integral, kernel);
  for (int i = 0; i < samples; ++i) {
    const double d = segment.start + (i + 0.5) * sample_length;
    const Point x = point_at(d);
    const double mu_s = ray.mu_s_at(d, x.radius);
    // x.radius >= the ground radius (point_at), as optical_lengths_to_infinity assumes.
    if (ray_hits_ground(x.radius, mu_s, p.earth_radius_m)) continue;  // in the Earth's shadow
    // The densities at x serve its length to the sun, its length along the view and the
    // sample's weights.
    const OpticalLengths rho = densities(profiles, x.radius);
    const OpticalLengths to_sun = lengths_to_infinity(profiles, x.radius, mu_s, rho);
    const OpticalLengths view =
        lengths_between(start_lengths, view_lengths_to_infinity(profiles, x, line_hits_ground, rho),
                        line_hits_ground);
    sums.add(view.rayleigh_m + to_sun.rayleigh_m, view.mie_m + to_sun.mie_m,
             sample_length * rho.rayleigh_m, sample_length * rho.mie_m);
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
  if (!transmittance_out.empty()) {
    const Point last = point_at(end);
    transmittance_into(atmosphere,
                       lengths_between(start_lengths,
                                       view_lengths_to_infinity(profiles, last, line_hits_ground,
                                                                densities(profiles, last.radius)),
                                       line_hits_ground),
                       transmittance_out.data());
  }
  return segment.hits_ground && end >= segment.end;
}

ScatteringAlongRay single_scattering(const AtmosphereSpectra& atmosphere, const RaySunGeometry& ray,
                                     int samples, double max_distance_m,
                                     TransmittanceKernel kernel) {
  const std::size_t n = atmosphere.rayleigh_scattering_per_m.size();
  std::vector<double> scratch(2 * n);
  const std::span<double> all(scratch);
  ScatteringAlongRay result{Spectrum(n), Spectrum(n), 0.0, false};
  result.hits_ground = single_scattering(
      atmosphere, ray, samples, max_distance_m, {result.radiance.data(), n},
      {result.transmittance.data(), n}, {all.subspan(0, n), all.subspan(n, n)}, kernel);
  const auto& p = atmosphere.parameters;
  const AtmosphereSegment segment =
      atmosphere_segment(ray.r_m, ray.mu, p.earth_radius_m, p.top_radius_m);
  result.length_m = std::max(0.0, std::min(segment.end, max_distance_m) - segment.start);
  return result;
}

}  // namespace clearsky::oneal
