// Sampling directions and binned phase-function integrals of Nishita96 (see
// nishita96_functions.h).
#include "models/nishita96/nishita96_functions.h"

#include <cmath>

#include "models/atmosphere/phase_functions.h"
#include "models/core/numeric.h"

namespace clearsky::nishita96 {

std::array<double, kSamplingDirections> sampling_angles_rad(double sun_zenith_rad) {
  const double half_pi = 0.5 * kPi;
  return {0.0,
          kPi,
          half_pi,
          -half_pi,
          sun_zenith_rad,
          sun_zenith_rad + kPi,
          sun_zenith_rad - half_pi,
          sun_zenith_rad + half_pi};
}

namespace {

// Index of the sampling direction nearest to w (largest dot product, the first on ties).
int nearest_direction(Vec3 w, const std::array<Vec3, kSamplingDirections>& sampling_directions) {
  int nearest = 0;
  double best = dot(w, sampling_directions[0]);
  for (int k = 1; k < kSamplingDirections; ++k) {
    const double candidate = dot(w, sampling_directions[k]);
    if (candidate > best) {
      best = candidate;
      nearest = k;
    }
  }
  return nearest;
}

// Sum over a bin of dOmega (1 + mu^2) / (1 + g^2 - 2 g mu)^(3/2), mu = v . w.
__attribute__((target_clones("avx2", "default"))) double cornette_shanks_sum(
    const double* x, const double* y, const double* z, const double* solid_angle, int count,
    Vec3 view, double g) {
  const double g2 = g * g;
  double sum = 0.0;
  for (int i = 0; i < count; ++i) {
    double mu = view.x * x[i] + view.y * y[i] + view.z * z[i];
    mu = mu > 1.0 ? 1.0 : (mu < -1.0 ? -1.0 : mu);
    const double denominator = 1.0 + g2 - 2.0 * g * mu;
    sum += solid_angle[i] * (1.0 + mu * mu) / (denominator * std::sqrt(denominator));
  }
  return sum;
}

}  // namespace

PhaseIntegrals binned_phase_integrals(
    Vec3 view, const std::array<Vec3, kSamplingDirections>& sampling_directions, double mie_g,
    int theta_cells) {
  PhaseIntegrals result;
  const double d_theta = kPi / theta_cells;
  const double d_phi = kPi / theta_cells;
  for (int i = 0; i < theta_cells; ++i) {
    const double theta = (i + 0.5) * d_theta;
    const double sin_theta = std::sin(theta);
    const double cos_theta = std::cos(theta);
    const double solid_angle = sin_theta * d_theta * d_phi;
    for (int j = 0; j < 2 * theta_cells; ++j) {
      const double phi = (j + 0.5) * d_phi;
      const Vec3 w{std::cos(phi) * sin_theta, std::sin(phi) * sin_theta, cos_theta};
      const double mu = clamp_cosine(dot(view, w));
      const int nearest = nearest_direction(w, sampling_directions);
      result.rayleigh[nearest] += rayleigh_phase(mu) * solid_angle;
      result.mie[nearest] += cornette_shanks_phase(mu, mie_g) * solid_angle;
    }
  }
  return result;
}

PhaseBins::PhaseBins(const std::array<Vec3, kSamplingDirections>& sampling_directions,
                     int theta_cells) {
  std::array<std::vector<Vec3>, kSamplingDirections> directions;
  std::array<std::vector<double>, kSamplingDirections> solid_angles;
  const double d_theta = kPi / theta_cells;
  const double d_phi = kPi / theta_cells;
  for (int i = 0; i < theta_cells; ++i) {
    const double theta = (i + 0.5) * d_theta;
    const double sin_theta = std::sin(theta);
    for (int j = 0; j < 2 * theta_cells; ++j) {
      const double phi = (j + 0.5) * d_phi;
      const Vec3 w{std::cos(phi) * sin_theta, std::sin(phi) * sin_theta, std::cos(theta)};
      const int k = nearest_direction(w, sampling_directions);
      directions[k].push_back(w);
      solid_angles[k].push_back(sin_theta * d_theta * d_phi);
    }
  }
  for (int k = 0; k < kSamplingDirections; ++k) {
    begin_[k] = static_cast<int>(x_.size());
    for (std::size_t i = 0; i < directions[k].size(); ++i) {
      const Vec3 w = directions[k][i];
      const double o = solid_angles[k][i];
      x_.push_back(w.x);
      y_.push_back(w.y);
      z_.push_back(w.z);
      solid_angle_.push_back(o);
      bin_solid_angle_[k] += o;
      auto& m = moments_[k];
      m[0] += o * w.x * w.x;
      m[1] += o * w.y * w.y;
      m[2] += o * w.z * w.z;
      m[3] += o * w.x * w.y;
      m[4] += o * w.x * w.z;
      m[5] += o * w.y * w.z;
    }
  }
  begin_[kSamplingDirections] = static_cast<int>(x_.size());
}

PhaseIntegrals PhaseBins::integrate(Vec3 v, double mie_g) const {
  PhaseIntegrals result;
  const double g2 = mie_g * mie_g;
  const double cs_scale = 3.0 / (8.0 * kPi) * (1.0 - g2) / (2.0 + g2);
  for (int k = 0; k < kSamplingDirections; ++k) {
    const auto& m = moments_[k];
    const double quadratic = m[0] * v.x * v.x + m[1] * v.y * v.y + m[2] * v.z * v.z +
                             2.0 * (m[3] * v.x * v.y + m[4] * v.x * v.z + m[5] * v.y * v.z);
    result.rayleigh[k] = 3.0 / (16.0 * kPi) * (bin_solid_angle_[k] + quadratic);
    const int b = begin_[k];
    result.mie[k] =
        cs_scale * cornette_shanks_sum(x_.data() + b, y_.data() + b, z_.data() + b,
                                       solid_angle_.data() + b, begin_[k + 1] - b, v, mie_g);
  }
  return result;
}

}  // namespace clearsky::nishita96
