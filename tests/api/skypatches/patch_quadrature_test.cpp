// The per-patch quadrature (api/skypatches/patch_quadrature.h): weights summing to each
// patch's solid angle (to 1e-8), integrals of known functions over the hemisphere, the
// refinement near the sun, and the node count the default order costs.
#include "api/skypatches/patch_quadrature.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace clearsky::api {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(PatchQuadrature, WeightsSumToEachPatchsSolidAngle) {
  for (int mf = 1; mf <= kMaxSkyPatchSubdivision; ++mf) {
    const SkyPatchScheme scheme(mf);
    const PatchQuadrature q =
        patch_quadrature(scheme, default_patch_quadrature_order(scheme), std::nullopt);
    const auto patches = scheme.sky_patches();
    ASSERT_EQ(q.first.size(), patches.size() + 1);
    for (std::size_t p = 0; p < patches.size(); ++p) {
      double sum = 0.0;
      for (std::size_t k = q.first[p]; k < q.first[p + 1]; ++k) {
        sum += q.weights_sr[k];
        const double altitude = 0.5 * kPi - q.views[k].zenith_rad;
        // Every node lies in its patch.
        EXPECT_EQ(scheme.patch_of(altitude, q.views[k].azimuth_rad), p + 1);
      }
      // Gauss-Legendre integrates cos(altitude) to 2e-9 with 2 nodes over a 2-degree band.
      EXPECT_NEAR(sum, patches[p].solid_angle_sr, 1e-8 * patches[p].solid_angle_sr) << mf << p;
    }
  }
}

TEST(PatchQuadrature, IntegratesSmoothFunctionsOverTheHemisphere) {
  const SkyPatchScheme scheme(1);
  const PatchQuadrature q =
      patch_quadrature(scheme, default_patch_quadrature_order(scheme), std::nullopt);
  double z2 = 0.0, z = 0.0, x2 = 0.0;
  for (std::size_t k = 0; k < q.views.size(); ++k) {
    const Vec3 d = q.views[k].unit_vector();
    z += q.weights_sr[k] * d.z;
    z2 += q.weights_sr[k] * d.z * d.z;
    x2 += q.weights_sr[k] * d.x * d.x;
  }
  EXPECT_NEAR(z, kPi, 1e-12);  // the horizontal irradiance of a unit sky
  EXPECT_NEAR(z2, 2.0 * kPi / 3.0, 1e-12);
  EXPECT_NEAR(x2, 2.0 * kPi / 3.0, 1e-12);
}

TEST(PatchQuadrature, RefinesThePatchesNearTheSun) {
  const SkyPatchScheme scheme(1);
  const PatchQuadratureOrder order = default_patch_quadrature_order(scheme);
  EXPECT_EQ(order.nodes_per_side, 8);
  const PatchQuadrature plain = patch_quadrature(scheme, order, std::nullopt);
  // 144 band patches x 64 and the cap 8 x 32.
  EXPECT_EQ(plain.views.size(), 144u * 64u + 256u);
  const SunPosition sun{40.0 * kPi / 180.0, 100.0 * kPi / 180.0};
  const PatchQuadrature refined = patch_quadrature(scheme, order, sun);
  const std::size_t sun_patch = scheme.patch_of(50.0 * kPi / 180.0, 100.0 * kPi / 180.0);
  EXPECT_EQ(refined.first[sun_patch] - refined.first[sun_patch - 1], 32u * 32u);
  // A patch on the other side of the sky keeps the plain order.
  const std::size_t opposite = scheme.patch_of(10.0 * kPi / 180.0, 280.0 * kPi / 180.0);
  EXPECT_EQ(refined.first[opposite] - refined.first[opposite - 1], 64u);
  // A sun below the horizon refines nothing.
  const PatchQuadrature night =
      patch_quadrature(scheme, order, SunPosition{100.0 * kPi / 180.0, 0.0});
  EXPECT_EQ(night.views.size(), plain.views.size());
}

}  // namespace
}  // namespace clearsky::api
