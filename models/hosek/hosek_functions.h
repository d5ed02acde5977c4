// The Hosek-Wilkie clear-sky model as pure functions (Hosek and Wilkie 2012, eq. 9; solar
// radiance function of Hosek and Wilkie 2013), on the tables of hosek_tables.h.
//
// Sky radiance of one channel, for a view at zenith angle theta and angle gamma from the sun:
//   L = (1 + A exp(B / (cos theta + 0.01)))
//       x (C + D exp(E gamma) + F cos^2 gamma + G chi(H, gamma) + I sqrt(cos theta)) x L_M,
//   chi(g, gamma) = (1 + cos^2 gamma) / (1 + g^2 - 2 g cos gamma)^(3/2)
// (the tables name the coefficients A..I in storage order: A, B, C, D, E, F, G, I (the
// zenith term), H (the anisotropy g); configuration index 7 multiplies sqrt(cos theta) and
// index 8 is g, as in the authors' code). Each coefficient and the scale L_M is a quintic
// Bezier curve in (solar elevation / (pi/2))^(1/3), interpolated linearly in turbidity
// (integer knots 1..10) and in ground albedo (knots 0 and 1).
//
// Angles in radians; the solar elevation is pi/2 - sun zenith and must be in [0, pi/2].
// Pure functions of immutable tables; thread-safe.
#pragma once

#include <array>
#include <cmath>

#include "models/hosek/hosek_tables.h"

namespace clearsky::hosek {

// One channel's distribution at a given turbidity, albedo and solar elevation.
struct Configuration {
  Coefficients coefficients{};
  double radiance_scale = 0;  // L_M
};

// Turbidity in [1, 10], albedo in [0, 1], solar elevation in [0, pi/2] (clamped).
Configuration cook(const SkyChannel& channel, double turbidity, double albedo,
                   double solar_elevation_rad);

// The view-dependent quantities of the distribution, shared by all channels.
struct ViewTerms {
  double gamma_rad = 0;
  double cos_gamma = 1;
  double cos2_gamma = 1;
  double sqrt_cos_theta = 1;
  double inverse_cos_theta_plus = 1;  // 1 / (cos theta + 0.01)
};

// cos_view_zenith is clamped to [0, 1] (views at or above the horizon); cos_gamma to [-1, 1].
ViewTerms view_terms(double cos_view_zenith, double cos_gamma);

// The distribution (without L_M) of a configuration.
inline double distribution(const Coefficients& c, const ViewTerms& v) {
  const double exp_term = std::exp(c[4] * v.gamma_rad);
  const double mie_base = 1.0 + c[8] * c[8] - 2.0 * c[8] * v.cos_gamma;
  // mie_base >= (1 - |g|)^2 > 0 for |g| < 1; the fitted g are in (0, 1).
  const double mie = (1.0 + v.cos2_gamma) / (mie_base * std::sqrt(mie_base));
  return (1.0 + c[0] * std::exp(c[1] * v.inverse_cos_theta_plus)) *
         (c[2] + c[3] * exp_term + c[5] * v.cos2_gamma + c[6] * mie + c[7] * v.sqrt_cos_theta);
}

inline double radiance(const Configuration& config, const ViewTerms& v) {
  return distribution(config.coefficients, v) * config.radiance_scale;
}

// ---- Solar disc (Hosek and Wilkie 2013) ----

// Angular radius of the solar disc the fit assumes: 0.51 degrees / 2.
inline constexpr double kSolarRadiusRad = 0.51 / 2.0 * 3.14159265358979323846 / 180.0;
// Solid angle the 2016 study used to turn the fit's solar radiance into an irradiance.
inline constexpr double kStudySunSolidAngleSr = 6.87e-5;

// Radiance at the centre of the solar disc seen through the atmosphere in band b, for the
// sun at solar_elevation_rad (>= 0; 0 below), W/(m2.sr.nm) with the fit's solar spectrum:
// a piecewise cubic in elevation over 45 pieces equally spaced in elevation^(1/3),
// interpolated linearly in turbidity.
double solar_centre_radiance(int band, double turbidity, double solar_elevation_rad);
// The same for all bands at once.
std::array<double, kBandCount> solar_centre_radiances(double turbidity, double solar_elevation_rad);

// Limb darkening of band b at cosine mu on the solar surface (1 at the disc centre).
double limb_darkening(int band, double mu);
// The cosine on the solar surface of a direction at angle gamma from the disc centre, or -1
// outside the disc.
double solar_surface_cosine(double gamma_rad);
// Integral over the fit's solar disc of the limb darkening of band b, sr.
double limb_darkened_disc_solid_angle(int band);

// ---- RGB and CIE XYZ versions (3 channels) ----

enum class Tristimulus { rgb, xyz };

struct TristimulusState {
  std::array<Configuration, 3> channels;
};

TristimulusState make_tristimulus_state(Tristimulus kind, double turbidity, double albedo,
                                        double solar_elevation_rad);
// Linear sRGB or CIE XYZ radiance, radiometric (W/(m2.sr) weighted by the colour matching
// functions, with the fit's solar spectrum): multiply Y by 683 lm/W for cd/m2.
std::array<double, 3> tristimulus_radiance(const TristimulusState& state, double view_zenith_rad,
                                           double gamma_rad);

}  // namespace clearsky::hosek
