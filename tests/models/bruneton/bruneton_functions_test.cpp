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

TEST(BrunetonFunctions, SunAndViewSunCosinesLandOnTheirTexels) {
  for (int i = 1; i < kRes.mu_s; ++i) {
    const double mu_s = texel_mu_s(i, kRes.mu_s);
    const Axis a = texture_axis(u_mu_s(mu_s, kRes.mu_s), kRes.mu_s);
    EXPECT_NEAR(a.i0 + a.f, i, 1e-6) << i;
  }
  // The mapping spans about [-0.2, 1], with 1 at the last texel.
  EXPECT_NEAR(texel_mu_s(kRes.mu_s - 1, kRes.mu_s), 1.0, 1e-12);
  EXPECT_LT(texel_mu_s(0, kRes.mu_s), kMinLookupMuS);
  for (int k = 0; k < kRes.nu; ++k) {
    const Axis a = nu_axis_4d(texel_nu(k, kRes.nu), kRes);
    EXPECT_EQ(a.i0, k);
    EXPECT_EQ(a.f, 0.0);
  }
  EXPECT_NEAR(radians_to_degrees(max_sun_zenith_rad()), 101.39, 0.01);
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
