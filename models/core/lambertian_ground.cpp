// The Lambertian ground of the single-scattering models (lambertian_ground.h).
#include "models/core/lambertian_ground.h"

#include <algorithm>
#include <cmath>

#include "models/core/numeric.h"

namespace clearsky {
namespace {

double node_cosine(int k) {
  return LambertianGround::kLowestSunCosine +
         (1.0 - LambertianGround::kLowestSunCosine) * k / (LambertianGround::kSunCosineNodes - 1);
}

}  // namespace

LambertianGround::LambertianGround(Spectrum albedo, Spectrum solar_irradiance,
                                   const std::function<Spectrum(double mu_s)>& sky_irradiance)
    : albedo_over_pi_(std::move(albedo)), solar_irradiance_(std::move(solar_irradiance)) {
  for (double& a : albedo_over_pi_) a /= kPi;
  sky_irradiance_.reserve(kSunCosineNodes);
  for (int k = 0; k < kSunCosineNodes; ++k)
    sky_irradiance_.push_back(sky_irradiance(node_cosine(k)));
}

Spectrum LambertianGround::sky_irradiance(double mu_s) const {
  Spectrum out(albedo_over_pi_.size(), 0.0);
  if (sky_irradiance_.empty() || !(mu_s >= kLowestSunCosine)) return out;
  const double x =
      std::min((mu_s - kLowestSunCosine) / (1.0 - kLowestSunCosine), 1.0) * (kSunCosineNodes - 1);
  const int k = std::min(static_cast<int>(x), kSunCosineNodes - 2);
  const double f = x - k;
  const Spectrum& a = sky_irradiance_[static_cast<std::size_t>(k)];
  const Spectrum& b = sky_irradiance_[static_cast<std::size_t>(k + 1)];
  for (std::size_t w = 0; w < out.size(); ++w) out[w] = (1.0 - f) * a[w] + f * b[w];
  return out;
}

void LambertianGround::add_reflected(double mu_s, std::span<const double> sun_transmittance,
                                     std::span<const double> view_transmittance,
                                     std::span<double> out) const {
  const Spectrum sky = sky_irradiance(mu_s);
  const double direct = std::max(mu_s, 0.0);
  for (std::size_t w = 0; w < out.size(); ++w) {
    const double irradiance = solar_irradiance_[w] * sun_transmittance[w] * direct + sky[w];
    out[w] += view_transmittance[w] * albedo_over_pi_[w] * irradiance;
  }
}

}  // namespace clearsky
