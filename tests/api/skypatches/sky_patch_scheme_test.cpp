// Tregenza and Reinhart patches in Radiance's numbering (api/skypatches/sky_patch_scheme.h):
// the counts genskyvec and gendaymtx produce, solid angles summing to the hemisphere, the
// numbering of reinhart.cal (bands from the horizon up, each from North clockwise, the cap
// last), and patch_of agreeing with the patches' own extents.
#include "api/skypatches/sky_patch_scheme.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace clearsky::api {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

TEST(SkyPatchScheme, CountsAreRadiances) {
  // With the ground: 146 (Tregenza), then 144 MF^2 + 2 (reinhart.cal's Rmax + 1).
  const std::size_t expected[] = {146, 578, 1298, 2306, 3602, 5186};
  for (int mf = 1; mf <= kMaxSkyPatchSubdivision; ++mf)
    EXPECT_EQ(SkyPatchScheme(mf).patch_count(), expected[mf - 1]) << mf;
  EXPECT_THROW(SkyPatchScheme(0), std::invalid_argument);
  EXPECT_THROW(SkyPatchScheme(kMaxSkyPatchSubdivision + 1), std::invalid_argument);
}

TEST(SkyPatchScheme, SolidAnglesSumToTheHemisphere) {
  for (int mf = 1; mf <= kMaxSkyPatchSubdivision; ++mf) {
    const SkyPatchScheme scheme(mf);
    double sum = 0.0;
    for (const SkyPatch& p : scheme.sky_patches()) {
      EXPECT_GT(p.solid_angle_sr, 0.0);
      sum += p.solid_angle_sr;
    }
    EXPECT_NEAR(sum, 2.0 * kPi, 1e-12) << mf;
  }
}

TEST(SkyPatchScheme, TregenzaNumbering) {
  const SkyPatchScheme tregenza(1);
  const auto p = tregenza.sky_patches();
  // Bands 12 degrees high (90 / 7.5); band 1 has 30 patches 12 degrees wide.
  EXPECT_NEAR(tregenza.band_height_rad(), 12.0 * kDeg, 1e-15);
  // Patch 1 (p[0]) is centred on North at 6 degrees of altitude, patch 2 is East of it.
  EXPECT_NEAR(p[0].centre_altitude_rad, 6.0 * kDeg, 1e-15);
  EXPECT_NEAR(p[0].centre_azimuth_rad, 0.0, 1e-15);
  EXPECT_NEAR(p[0].min_azimuth_rad, -6.0 * kDeg, 1e-15);
  EXPECT_NEAR(p[1].centre_azimuth_rad, 12.0 * kDeg, 1e-15);
  // Patch 31 starts the second band; 61 the third (24 patches, 15 degrees).
  EXPECT_NEAR(p[30].centre_altitude_rad, 18.0 * kDeg, 1e-15);
  EXPECT_NEAR(p[30].centre_azimuth_rad, 0.0, 1e-15);
  EXPECT_NEAR(p[61].centre_azimuth_rad - p[60].centre_azimuth_rad, 15.0 * kDeg, 1e-15);
  // The row counts 30, 30, 24, 24, 18, 12, 6 and the cap.
  EXPECT_NEAR(p[138].centre_altitude_rad, 78.0 * kDeg, 1e-14);
  EXPECT_NEAR(p[143].centre_altitude_rad, 78.0 * kDeg, 1e-14);
  EXPECT_TRUE(p[144].cap);
  EXPECT_NEAR(p[144].min_altitude_rad, 84.0 * kDeg, 1e-14);
  EXPECT_NEAR(p[144].solid_angle_sr, 2.0 * kPi * (1.0 - std::cos(6.0 * kDeg)), 1e-15);
  // Tregenza's (1987) band patch solid angles: 0.0435 sr for the first band.
  EXPECT_NEAR(p[0].solid_angle_sr, 12.0 * kDeg * std::sin(12.0 * kDeg), 1e-15);
  EXPECT_NEAR(p[0].solid_angle_sr, 0.0435, 5e-5);
}

TEST(SkyPatchScheme, PatchOfFindsEachPatchFromInside) {
  for (int mf : {1, 2, 4, 6}) {
    const SkyPatchScheme scheme(mf);
    const auto patches = scheme.sky_patches();
    for (std::size_t i = 0; i < patches.size(); ++i) {
      const SkyPatch& p = patches[i];
      // Points near each corner (inside) and the centre, at any turn of azimuth.
      for (double fa : {0.01, 0.5, 0.99}) {
        for (double fz : {0.01, 0.5, 0.99}) {
          const double alt = p.min_altitude_rad + fa * (p.max_altitude_rad - p.min_altitude_rad);
          const double az = p.min_azimuth_rad + fz * (p.max_azimuth_rad - p.min_azimuth_rad);
          EXPECT_EQ(scheme.patch_of(alt, az), i + 1) << mf << " " << i;
          EXPECT_EQ(scheme.patch_of(alt, az + 2.0 * kPi), i + 1) << mf << " " << i;
          EXPECT_EQ(scheme.patch_of(alt, az - 4.0 * kPi), i + 1) << mf << " " << i;
        }
      }
    }
    EXPECT_EQ(scheme.patch_of(0.5 * kPi, 1.0), patches.size());
    EXPECT_EQ(scheme.patch_of(-0.01, 1.0), 0u);
    EXPECT_THROW(scheme.patch_of(0.1, std::nan("")), std::invalid_argument);
    EXPECT_THROW(scheme.patch_of(std::nan(""), 0.0), std::invalid_argument);
  }
}

}  // namespace
}  // namespace clearsky::api
