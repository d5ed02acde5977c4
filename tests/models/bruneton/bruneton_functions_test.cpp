// The Bruneton 2008 parameterisation: lookups at a texel's own (r, mu, mu_s, nu) land on
// that texel, the ray-length limit is the distance to the ground or the limit sphere.
#include "models/bruneton/bruneton_functions.h"

#include <gtest/gtest.h>

#include <cmath>

namespace clearsky::bruneton {
namespace {

const ShellGeometry kShell{};
const Resolution kRes{};

TEST(BrunetonFunctions, LimitDistanceIsGroundOrLimitSphere) {
  const double r = kShell.bottom_m + 1000.0;
  // Straight up: to the limit sphere.
  EXPECT_NEAR(limit_distance(r, 1.0, kShell), kShell.limit_m - r, 1e-6);
  // Straight down: to the ground.
  EXPECT_NEAR(limit_distance(r, -1.0, kShell), 1000.0, 1e-6);
  // Horizontal from the ground touches the ground at distance 0 (2008 code); slightly up,
  // the ray reaches the limit sphere.
  EXPECT_EQ(limit_distance(kShell.bottom_m, 0.0, kShell), 0.0);
  const double mu = 1e-3;
  EXPECT_NEAR(
      limit_distance(kShell.bottom_m, mu, kShell),
      -kShell.bottom_m * mu + std::sqrt(kShell.bottom_m * kShell.bottom_m * (mu * mu - 1.0) +
                                        kShell.limit_m * kShell.limit_m),
      1e-6);
}

TEST(BrunetonFunctions, HorizonCosine) {
  EXPECT_EQ(horizon_mu(kShell.bottom_m, kShell), 0.0);
  const double r = kShell.bottom_m + 10e3;
  EXPECT_NEAR(horizon_mu(r, kShell), -std::sqrt(1.0 - std::pow(kShell.bottom_m / r, 2)), 1e-15);
}

TEST(BrunetonFunctions, TextureAxisFollowsTextureSemantics) {
  // Texel centres.
  Axis a = texture_axis(2.5 / 8.0, 8);
  EXPECT_EQ(a.i0, 2);
  EXPECT_EQ(a.f, 0.0);
  // Halfway between texels 2 and 3.
  a = texture_axis(3.0 / 8.0, 8);
  EXPECT_EQ(a.i0, 2);
  EXPECT_EQ(a.i1, 3);
  EXPECT_NEAR(a.f, 0.5, 1e-12);
  // Clamped at both ends.
  a = texture_axis(-1.0, 8);
  EXPECT_EQ(a.i0, 0);
  EXPECT_EQ(a.i1, 0);
  a = texture_axis(2.0, 8);
  EXPECT_EQ(a.i0, 7);
  EXPECT_EQ(a.i1, 7);
}

TEST(BrunetonFunctions, LayersLandOnTheirTexels) {
  for (int layer = 1; layer < kRes.r - 1; ++layer) {
    const Layer l = layer_geometry(layer, kRes.r, kShell);
    const Axis a = r_axis_4d(l.r, kRes, kShell);
    EXPECT_EQ(a.i0, layer);
    EXPECT_EQ(a.f, 0.0);
  }
  // The nudged end layers stay inside the shell.
  EXPECT_NEAR(layer_geometry(0, kRes.r, kShell).r, kShell.bottom_m + 10.0, 1e-6);
  EXPECT_NEAR(layer_geometry(kRes.r - 1, kRes.r, kShell).r, kShell.top_m - 1.0, 1e-6);
}

TEST(BrunetonFunctions, ViewCosinesLandOnTheirTexels) {
  // Rows away from the clamped ends (nadir, zenith, the 0.999 factor at the horizon, and the
  // ground rows the 2008 code clamps to mu_horizon - 0.001) map back to their own texel.
  for (int layer : {1, 7, 20, 30}) {
    const Layer l = layer_geometry(layer, kRes.r, kShell);
    for (int j = 2; j < kRes.mu - 2; ++j) {
      if (j == kRes.mu / 2 - 1 || j == kRes.mu / 2) continue;
      const double mu = texel_mu(j, kRes.mu, l, kShell);
      if (std::abs(mu - (horizon_mu(l.r, kShell) - 0.001)) < 1e-12 || std::abs(mu) > 1.0 - 1e-9)
        continue;
      ASSERT_GE(mu, -1.0);
      ASSERT_LE(mu, 1.0);
      const Axis a = mu_axis_4d(l.r, mu, kRes, kShell);
      const double position = a.i0 + a.f;
      EXPECT_NEAR(position, j, 1e-6) << "layer " << layer << " row " << j;
      // The lower half looks at the ground, the upper half at the sky.
      EXPECT_EQ(mu < horizon_mu(l.r, kShell), j < kRes.mu / 2) << "layer " << layer << " row " << j;
    }
  }
}

// A horizontal view from the top of the atmosphere: Rt^2 - r^2 (1 - mu^2) is 0, but summed
// from terms of order r^2 it rounded to -1.2e-4 m^2 for this shell, which safe_sqrt's
// assertion took for a clearly negative value (found by fuzz/table_cache_fuzz.cpp). It maps
// to the sky half's first row.
TEST(BrunetonFunctions, GrazingViewFromTheTopIsTheSkyHalfsFirstRow) {
  const ShellGeometry shell{6359999.90625, 6420000.0, 6421000.0};
  const Axis a = mu_axis_4d(shell.top_m, 0.0, kRes, shell);
  EXPECT_EQ(a.i0, kRes.mu / 2);
  EXPECT_NEAR(a.f, 0.0, 1e-9);
}

TEST(BrunetonFunctions, SunAndViewSunCosinesLandOnTheirTexels) {
  for (int i = 1; i < kRes.mu_s; ++i) {
    const double mu_s = texel_mu_s(i, kRes.mu_s, kRes.sun);
    const Axis a = texture_axis(u_mu_s(mu_s, kRes.mu_s, kRes.sun), kRes.mu_s);
    EXPECT_NEAR(a.i0 + a.f, i, 1e-6) << i;
  }
  // The mapping spans about [-0.2, 1], with 1 at the last texel.
  EXPECT_NEAR(texel_mu_s(kRes.mu_s - 1, kRes.mu_s, kRes.sun), 1.0, 1e-12);
  EXPECT_LT(texel_mu_s(0, kRes.mu_s, kRes.sun), kMinLookupMuS);
  for (int k = 0; k < kRes.nu; ++k) {
    const Axis a = nu_axis_4d(texel_nu(k, kRes.nu), kRes);
    EXPECT_EQ(a.i0, k);
    EXPECT_EQ(a.f, 0.0);
  }
  EXPECT_FALSE(kRes.sun.extended);
  EXPECT_EQ(kRes.sun.lookup_min_mu_s, kMinLookupMuS);
  EXPECT_NEAR(radians_to_degrees(kRes.sun.max_sun_zenith_rad()), 101.39, 0.01);
  // The 2008 irradiance table: mu_s from -0.2 to 1.
  EXPECT_EQ(irradiance_texel_mu_s(0, kRes.irradiance_mu_s, kRes.sun), -0.2);
  EXPECT_NEAR(irradiance_texel_mu_s(kRes.irradiance_mu_s - 1, kRes.irradiance_mu_s, kRes.sun), 1.0,
              1e-15);
  EXPECT_EQ(irradiance_u_mu_s(-0.2, kRes.sun), 0.0);
}

// The extended sun range: the same tan family with its offset solved so that the first texel
// holds cos(max sun zenith); monotone, round-tripping, ending at mu_s = 1, and the lookup clamps
// exactly at the first texel.
TEST(BrunetonFunctions, ExtendedSunRangeMapping) {
  for (double max_deg : {95.0, 105.0, 110.0, 120.0}) {
    const SunRange s = SunRange::up_to(degrees_to_radians(max_deg));
    const double mu_min = std::cos(degrees_to_radians(max_deg));
    EXPECT_TRUE(s.extended);
    EXPECT_NEAR(radians_to_degrees(s.max_sun_zenith_rad()), max_deg, 1e-9);
    EXPECT_GT(s.offset, 0.0);
    EXPECT_LT(s.offset, kPi / (2.0 * kMuSAngle) - 1.0);
    EXPECT_EQ(s.offset<0.26, max_deg> 101.39) << max_deg;
    for (int n : {8, 32}) {
      EXPECT_NEAR(texel_mu_s(0, n, s), mu_min, 1e-12) << max_deg;
      EXPECT_NEAR(texel_mu_s(n - 1, n, s), 1.0, 1e-12) << max_deg;
      for (int i = 1; i < n; ++i) {
        const double mu_s = texel_mu_s(i, n, s);
        EXPECT_GT(mu_s, texel_mu_s(i - 1, n, s));
        const Axis a = texture_axis(u_mu_s(mu_s, n, s), n);
        EXPECT_NEAR(a.i0 + a.f, i, 1e-6) << max_deg << " " << i;
      }
      // At and beyond the range: the first texel, alone.
      for (double mu_s : {mu_min, mu_min - 0.05, -1.0}) {
        const Axis a = texture_axis(u_mu_s(mu_s, n, s), n);
        EXPECT_EQ(a.i0, 0) << mu_s;
        EXPECT_NEAR(a.f, 0.0, 1e-6) << mu_s;
      }
    }
    EXPECT_NEAR(irradiance_texel_mu_s(0, 64, s), mu_min, 1e-15);
    EXPECT_NEAR(irradiance_texel_mu_s(63, 64, s), 1.0, 1e-15);
    EXPECT_NEAR(irradiance_u_mu_s(mu_min, s), 0.0, 1e-15);
    EXPECT_NEAR(irradiance_u_mu_s(1.0, s), 1.0, 1e-15);
  }
  // The wider the range, the smaller the offset (the fewer texels near the horizon).
  EXPECT_GT(SunRange::up_to(degrees_to_radians(105.0)).offset,
            SunRange::up_to(degrees_to_radians(110.0)).offset);
  EXPECT_NEAR(SunRange::up_to(degrees_to_radians(110.0)).offset, 0.1853, 1e-4);
}

TEST(BrunetonFunctions, TransmittanceParameterisationRoundTrips) {
  for (int i = 0; i < kRes.transmittance_mu; i += 17) {
    const double mu = transmittance_texel_mu(i, kRes.transmittance_mu);
    EXPECT_NEAR(transmittance_u_mu(mu) * kRes.transmittance_mu - 0.5, i, 1e-9);
  }
  for (int j = 0; j < kRes.transmittance_r; j += 5) {
    const double r = transmittance_texel_r(j, kRes.transmittance_r, kShell);
    EXPECT_NEAR(transmittance_u_r(r, kShell) * kRes.transmittance_r - 0.5, j, 1e-9);
  }
}

}  // namespace
}  // namespace clearsky::bruneton
