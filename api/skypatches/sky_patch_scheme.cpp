// Tregenza and Reinhart patches in Radiance's numbering (sky_patch_scheme.h).
#include "api/skypatches/sky_patch_scheme.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace clearsky::api {

namespace {

constexpr double kPi = std::numbers::pi;
// Patches per Tregenza row, horizon to the row below the cap (reinhart.cal's tnaz).
constexpr int kTregenzaRow[] = {30, 30, 24, 24, 18, 12, 6};

}  // namespace

SkyPatchScheme::SkyPatchScheme(int subdivision) : subdivision_(subdivision) {
  if (subdivision < 1 || subdivision > kMaxSkyPatchSubdivision)
    throw std::invalid_argument("sky patch subdivision must be in [1, " +
                                std::to_string(kMaxSkyPatchSubdivision) + "]");
  const int bands = 7 * subdivision;
  band_height_rad_ = 0.5 * kPi / (bands + 0.5);
  for (int r = 0; r < bands; ++r) {
    band_first_.push_back(patches_.size());
    const int n = subdivision * kTregenzaRow[r / subdivision];
    const double width = 2.0 * kPi / n;
    const double bottom = r * band_height_rad_;
    const double top = (r + 1) * band_height_rad_;
    for (int c = 0; c < n; ++c) {
      SkyPatch p;
      p.min_altitude_rad = bottom;
      p.max_altitude_rad = top;
      p.min_azimuth_rad = (c - 0.5) * width;
      p.max_azimuth_rad = (c + 0.5) * width;
      p.centre_altitude_rad = (r + 0.5) * band_height_rad_;
      p.centre_azimuth_rad = c * width;
      p.solid_angle_sr = width * (std::sin(top) - std::sin(bottom));
      patches_.push_back(p);
    }
  }
  band_first_.push_back(patches_.size());
  SkyPatch cap;
  cap.min_altitude_rad = bands * band_height_rad_;
  cap.max_altitude_rad = 0.5 * kPi;
  cap.min_azimuth_rad = 0.0;
  cap.max_azimuth_rad = 2.0 * kPi;
  cap.centre_altitude_rad = 0.5 * kPi;
  cap.centre_azimuth_rad = 0.0;
  cap.solid_angle_sr = 2.0 * kPi * (1.0 - std::cos(0.5 * band_height_rad_));
  cap.cap = true;
  patches_.push_back(cap);
}

std::size_t SkyPatchScheme::patch_of(double altitude_rad, double azimuth_rad) const {
  if (!std::isfinite(altitude_rad) || !std::isfinite(azimuth_rad))
    throw std::invalid_argument("sky patch of a direction that is not finite");
  if (altitude_rad < 0.0) return 0;
  const int bands = 7 * subdivision_;
  const int r = static_cast<int>(std::floor(altitude_rad / band_height_rad_));
  if (r >= bands) return patches_.size();  // the cap, the last patch
  const std::size_t first = band_first_[static_cast<std::size_t>(r)];
  const auto n = static_cast<long>(band_first_[static_cast<std::size_t>(r) + 1] - first);
  const double turns = azimuth_rad / (2.0 * kPi);
  auto c = static_cast<long>(std::floor((turns - std::floor(turns)) * n + 0.5));
  c %= n;
  return first + static_cast<std::size_t>(c) + 1;
}

PatchGeometry patch_geometry(const SkyPatchScheme& scheme, std::size_t k) {
  constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
  if (k == 0) return {-90.0, 0.0, 2.0 * std::numbers::pi};
  const SkyPatch& patch = scheme.sky_patches()[k - 1];
  return {patch.centre_altitude_rad * kDegreesPerRadian,
          patch.centre_azimuth_rad * kDegreesPerRadian, patch.solid_angle_sr};
}

}  // namespace clearsky::api
