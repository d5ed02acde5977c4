// The sky subdivisions of Radiance's daylight-coefficient tools (docs/building-energy.md):
// Tregenza's 145 patches (Tregenza 1987, "Subdivision of the sky hemisphere for luminance
// measurements", Lighting Research and Technology 19(1)) and Reinhart's subdivision of each of
// them into MF x MF (Reinhart's MF: 1 is Tregenza), numbered as Radiance's reinhart.cal,
// genskyvec and gendaymtx number them:
//  - patch 0 is the ground (the whole lower hemisphere, 2 pi sr);
//  - then 7 MF bands of equal altitude height alpha = 90 / (7 MF + 0.5) degrees, from the
//    horizon up, with MF x (30, 30, 24, 24, 18, 12, 6) patches in the MF bands of each of
//    Tregenza's rows; within a band, patch c is centred on the azimuth c x 360 / n degrees
//    clockwise from North (Radiance's +Y towards +X, East) and spans half a patch width on
//    each side, so the first patch of a band straddles North;
//  - the last patch is the zenith cap, from 90 - alpha / 2 degrees of altitude up.
// Solid angles are exact: a band patch spans (sin(top) - sin(bottom)) x width sr, the cap
// 2 pi (1 - cos(alpha / 2)); the sky patches sum to 2 pi.
// Counts with the ground: MF 1: 146, 2: 578, 3: 1298, 4: 2306, 5: 3602, 6: 5186.
// Immutable after construction; thread-safe.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace clearsky::api {

// Reinhart MF accepted (bounded work per request; Radiance's tools use 1 to 6 in practice).
inline constexpr int kMaxSkyPatchSubdivision = 6;

struct SkyPatch {
  double min_altitude_rad = 0;
  double max_altitude_rad = 0;
  // Clockwise from North; min may be negative (a patch straddling North). The cap: 0 to 2 pi.
  double min_azimuth_rad = 0;
  double max_azimuth_rad = 0;
  double centre_altitude_rad = 0;  // the cap: pi / 2
  double centre_azimuth_rad = 0;   // in [0, 2 pi); the cap: 0
  double solid_angle_sr = 0;
  bool cap = false;
};

class SkyPatchScheme {
 public:
  // subdivision: Reinhart's MF in [1, kMaxSkyPatchSubdivision]; std::invalid_argument beyond.
  explicit SkyPatchScheme(int subdivision);

  int subdivision() const { return subdivision_; }
  // Band height alpha, radians.
  double band_height_rad() const { return band_height_rad_; }
  // The sky patches: sky_patches()[i] is Radiance's patch i + 1.
  std::span<const SkyPatch> sky_patches() const { return patches_; }
  // Sky patches plus the ground.
  std::size_t patch_count() const { return patches_.size() + 1; }
  // Radiance's number (1 ..) of the sky patch holding the direction (altitude in [0, pi / 2],
  // azimuth clockwise from North, any turn); 0 (the ground) for an altitude below 0;
  // std::invalid_argument for a direction that is not finite.
  std::size_t patch_of(double altitude_rad, double azimuth_rad) const;

 private:
  int subdivision_;
  double band_height_rad_;
  std::vector<SkyPatch> patches_;
  std::vector<std::size_t> band_first_;  // index into patches_ of each band's first patch
};

// Radiance's patch k (0 the ground) as an answer gives it: its centre's altitude and azimuth
// (degrees; the ground's centre is the nadir) and its solid angle (sr; 2 pi for the ground).
struct PatchGeometry {
  double altitude_deg = 0, azimuth_deg = 0, solid_angle_sr = 0;
};
PatchGeometry patch_geometry(const SkyPatchScheme& scheme, std::size_t k);

}  // namespace clearsky::api
