// The limb-darkened solar disc spread over a skydome's pixels (sun_disc.h).
#include "api/skydome/sun_disc.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "models/core/numeric.h"
#include "models/hosek/hosek_functions.h"
#include "models/hosek/hosek_tables.h"

namespace clearsky::api {

namespace {

constexpr int kRings = 64;
constexpr int kAzimuths = 384;

}  // namespace

double solar_limb_darkening(double wavelength_nm, double mu) {
  using hosek::band_wavelength_nm;
  using hosek::kBandCount;
  const double position =
      std::clamp((wavelength_nm - band_wavelength_nm(0)) / hosek::kBandSpacingNm, 0.0,
                 static_cast<double>(kBandCount - 1));
  const int band = std::min(static_cast<int>(position), kBandCount - 2);
  const double t = position - band;
  return (1.0 - t) * hosek::limb_darkening(band, mu) + t * hosek::limb_darkening(band + 1, mu);
}

double sun_disc_solid_angle_sr() {
  return 2.0 * kPi * (1.0 - std::cos(kSunAngularRadiusDeg * kDegree));
}

SolarDiscPixels::SolarDiscPixels(const SkydomeProjection& projection, const SkyDirection& sun,
                                 std::span<const double> wavelengths_nm,
                                 std::span<const double> direct_normal_w_m2_nm) {
  const std::size_t n = wavelengths_nm.size();
  const double radius_rad = kSunAngularRadiusDeg * kDegree;
  // A frame around the sun's direction.
  const Vec3 s = sun.unit_vector();
  const Vec3 helper = std::abs(s.z) < 0.9 ? Vec3{0.0, 0.0, 1.0} : Vec3{1.0, 0.0, 0.0};
  const Vec3 e1 = normalize(cross(s, helper));
  const Vec3 e2 = cross(s, e1);

  // Limb darkening of each ring at each wavelength, and each ring's weight per (pixel, ring).
  std::vector<double> ring_rho(kRings), ring_solid_angle(kRings);
  std::vector<double> limb(static_cast<std::size_t>(kRings) * n);
  const double d_rho = radius_rad / kRings, d_psi = 2.0 * kPi / kAzimuths;
  for (int j = 0; j < kRings; ++j) {
    const double rho = (j + 0.5) * d_rho;
    ring_rho[j] = rho;
    ring_solid_angle[j] = std::sin(rho) * d_rho * d_psi;  // of one sample of the ring
    const double ratio = std::sin(rho) / std::sin(radius_rad);
    const double mu = safe_sqrt(1.0 - ratio * ratio);
    for (std::size_t w = 0; w < n; ++w)
      limb[static_cast<std::size_t>(j) * n + w] = solar_limb_darkening(wavelengths_nm[w], mu);
  }
  // The whole disc's limb-darkened solid angle per wavelength (hidden samples included).
  std::vector<double> total(n, 0.0);
  for (int j = 0; j < kRings; ++j)
    for (std::size_t w = 0; w < n; ++w)
      total[w] += kAzimuths * ring_solid_angle[j] * limb[static_cast<std::size_t>(j) * n + w];

  std::map<std::pair<int, int>, std::vector<double>> rings_of_pixel;  // (y, x) -> per ring
  for (int j = 0; j < kRings; ++j) {
    const double c = std::cos(ring_rho[j]), sn = std::sin(ring_rho[j]);
    for (int k = 0; k < kAzimuths; ++k) {
      const double psi = (k + 0.5) * d_psi;
      const Vec3 d = c * s + sn * (std::cos(psi) * e1 + std::sin(psi) * e2);
      if (d.z < 0.0) continue;  // hidden by the ground
      int x = 0, y = 0;
      if (!projection.pixel(SkyDirection::from_unit_vector(normalize(d)), x, y)) continue;
      auto& weights = rings_of_pixel[{y, x}];
      if (weights.empty()) weights.assign(kRings, 0.0);
      weights[static_cast<std::size_t>(j)] += ring_solid_angle[j];
    }
  }
  for (const auto& [yx, weights] : rings_of_pixel) {
    Pixel p;
    p.y = yx.first;
    p.x = yx.second;
    const double pixel_sr = projection.pixel_solid_angle_sr(p.x, p.y);
    p.radiance.assign(n, 0.0);
    for (std::size_t w = 0; w < n; ++w) {
      if (!(total[w] > 0.0)) continue;
      double share = 0.0;
      for (int j = 0; j < kRings; ++j)
        share += weights[static_cast<std::size_t>(j)] * limb[static_cast<std::size_t>(j) * n + w];
      p.radiance[w] = direct_normal_w_m2_nm[w] * share / total[w] / pixel_sr;
    }
    pixels_.push_back(std::move(p));
  }
  if (!pixels_.empty()) {
    first_row_ = pixels_.front().y;
    last_row_ = pixels_.back().y;
  }
}

const SolarDiscPixels::Pixel* SolarDiscPixels::find(int x, int y) const {
  if (!covers_row(y)) return nullptr;
  const auto it = std::lower_bound(pixels_.begin(), pixels_.end(), std::pair{y, x},
                                   [](const Pixel& p, const std::pair<int, int>& key) {
                                     return std::pair{p.y, p.x} < key;
                                   });
  if (it == pixels_.end() || it->y != y || it->x != x) return nullptr;
  return &*it;
}

std::size_t SolarDiscPixels::memory_bytes() const {
  std::size_t bytes = sizeof(*this);
  for (const Pixel& p : pixels_) bytes += sizeof(Pixel) + p.radiance.capacity() * sizeof(double);
  return bytes;
}

}  // namespace clearsky::api
