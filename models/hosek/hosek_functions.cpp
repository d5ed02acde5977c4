// The Hosek-Wilkie distribution, its Bezier/turbidity/albedo interpolation, the solar disc
// radiance and the tristimulus versions.
#include "models/hosek/hosek_functions.h"

#include <algorithm>
#include <cmath>

#include "models/core/numeric.h"
#include "models/core/quadrature.h"

namespace clearsky::hosek {
namespace {

// Bernstein weights of the quintic Bezier curve at t.
std::array<double, kControlPoints> bezier_weights(double t) {
  const double s = 1.0 - t;
  const double t2 = t * t, t3 = t2 * t, t4 = t3 * t, t5 = t4 * t;
  const double s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
  return {s5, 5.0 * s4 * t, 10.0 * s3 * t2, 10.0 * s2 * t3, 5.0 * s * t4, t5};
}

// The (albedo, turbidity) knots and weights of a bilinear interpolation: at most 4 terms.
struct Knot {
  int albedo = 0;
  int turbidity = 0;  // 0-based (turbidity 1 -> 0)
  double weight = 0;
};

std::array<Knot, 4> knots(double turbidity, double albedo) {
  // The authors' code: the integer part selects the lower knot; turbidity 10 uses it alone.
  const double t = std::clamp(turbidity, 1.0, static_cast<double>(kTurbidityCount));
  const int low = static_cast<int>(t);  // 1..10
  const double fraction = low == kTurbidityCount ? 0.0 : t - low;
  const int high = std::min(low + 1, kTurbidityCount);
  const double a = std::clamp(albedo, 0.0, 1.0);
  return {Knot{0, low - 1, (1.0 - a) * (1.0 - fraction)}, Knot{1, low - 1, a * (1.0 - fraction)},
          Knot{0, high - 1, (1.0 - a) * fraction}, Knot{1, high - 1, a * fraction}};
}

double bezier_parameter(double solar_elevation_rad) {
  return std::cbrt(std::clamp(solar_elevation_rad, 0.0, 0.5 * kPi) / (0.5 * kPi));
}

}  // namespace

Configuration cook(const SkyChannel& channel, double turbidity, double albedo,
                   double solar_elevation_rad) {
  const auto bernstein = bezier_weights(bezier_parameter(solar_elevation_rad));
  Configuration config;
  for (const Knot& knot : knots(turbidity, albedo)) {
    if (knot.weight == 0.0) continue;
    const auto& points = channel.coefficients[knot.albedo][knot.turbidity];
    const auto& scales = channel.radiance[knot.albedo][knot.turbidity];
    for (int p = 0; p < kControlPoints; ++p) {
      const double w = knot.weight * bernstein[p];
      for (int k = 0; k < kCoefficientCount; ++k) config.coefficients[k] += w * points[p][k];
      config.radiance_scale += w * scales[p];
    }
  }
  return config;
}

ViewTerms view_terms(double cos_view_zenith, double cos_gamma) {
  const double mu = std::clamp(cos_view_zenith, 0.0, 1.0);
  const double cg = std::clamp(cos_gamma, -1.0, 1.0);
  ViewTerms v;
  v.gamma_rad = std::acos(cg);
  v.cos_gamma = cg;
  v.cos2_gamma = cg * cg;
  v.sqrt_cos_theta = std::sqrt(mu);
  v.inverse_cos_theta_plus = 1.0 / (mu + 0.01);
  return v;
}

std::array<double, kBandCount> solar_centre_radiances(double turbidity,
                                                      double solar_elevation_rad) {
  std::array<double, kBandCount> radiance{};
  if (!(solar_elevation_rad >= 0.0)) return radiance;  // the disc centre is below the horizon
  const double elevation = std::min(solar_elevation_rad, 0.5 * kPi);
  // Turbidity knots as in the authors' code: turbidity 10 is the upper end of [9, 10].
  const double t = std::clamp(turbidity, 1.0, static_cast<double>(kTurbidityCount));
  int low = static_cast<int>(t) - 1;
  double fraction = t - (low + 1);
  if (low >= kTurbidityCount - 1) {
    low = kTurbidityCount - 2;
    fraction = 1.0;
  }
  const int segment = std::min(
      static_cast<int>(std::cbrt(elevation / (0.5 * kPi)) * kSolarSegments), kSolarSegments - 1);
  const double start = std::pow(static_cast<double>(segment) / kSolarSegments, 3.0) * (0.5 * kPi);
  const double x = elevation - start;
  const auto& solar = Tables::get().solar;
  for (int band = 0; band < kBandCount; ++band) {
    const auto cubic = [&](int turbidity_index) {
      const auto& c = solar[band][turbidity_index][segment];
      return ((c[0] * x + c[1]) * x + c[2]) * x + c[3];
    };
    radiance[band] = (1.0 - fraction) * cubic(low) + fraction * cubic(low + 1);
  }
  return radiance;
}

double solar_centre_radiance(int band, double turbidity, double solar_elevation_rad) {
  return solar_centre_radiances(turbidity, solar_elevation_rad)[band];
}

double limb_darkening(int band, double mu) {
  const auto& c = Tables::get().limb_darkening[band];
  double value = 0.0;
  for (int k = kLimbDarkeningOrder - 1; k >= 0; --k) value = value * mu + c[k];
  return value;
}

double solar_surface_cosine(double gamma_rad) {
  if (!(gamma_rad >= 0.0) || gamma_rad > kSolarRadiusRad) return -1.0;
  const double ratio = std::sin(gamma_rad) / std::sin(kSolarRadiusRad);
  return safe_sqrt(1.0 - ratio * ratio);
}

double limb_darkened_disc_solid_angle(int band) {
  // With s = sin(gamma) = S sqrt(1 - mu^2), S = sin(radius): d Omega = 2 pi sin(gamma) d gamma
  // = 2 pi S^2 mu / cos(gamma) d mu, a smooth integrand in mu on [0, 1].
  const double s = std::sin(kSolarRadiusRad);
  double sum = 0.0;
  for (const auto& [mu, w] : gauss_legendre(12, 0.0, 1.0)) {
    const double cos_gamma = std::sqrt(1.0 - s * s * (1.0 - mu * mu));
    sum += w * limb_darkening(band, mu) * mu / cos_gamma;
  }
  return 2.0 * kPi * s * s * sum;
}

TristimulusState make_tristimulus_state(Tristimulus kind, double turbidity, double albedo,
                                        double solar_elevation_rad) {
  const auto& channels = kind == Tristimulus::rgb ? Tables::get().rgb : Tables::get().xyz;
  TristimulusState state;
  for (int c = 0; c < 3; ++c)
    state.channels[c] = cook(channels[c], turbidity, albedo, solar_elevation_rad);
  return state;
}

std::array<double, 3> tristimulus_radiance(const TristimulusState& state, double view_zenith_rad,
                                           double gamma_rad) {
  const ViewTerms v = view_terms(std::cos(view_zenith_rad), std::cos(gamma_rad));
  return {radiance(state.channels[0], v), radiance(state.channels[1], v),
          radiance(state.channels[2], v)};
}

}  // namespace clearsky::hosek
