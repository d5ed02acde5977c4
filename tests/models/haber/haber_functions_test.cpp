// Layers of equal Rayleigh mass and the layered transmittance of the Haber model.
#include "models/haber/haber_functions.h"

#include <gtest/gtest.h>

#include <cmath>

#include "models/core/numeric.h"

namespace clearsky::haber {
namespace {

const LayeredAtmosphere kLayers(6360e3, 35e3, 50, 8000.0, 1200.0);

TEST(HaberLayers, EachLayerHoldsTheSameRayleighMass) {
  EXPECT_DOUBLE_EQ(kLayers.boundary_height_m(0), 0.0);
  EXPECT_NEAR(kLayers.boundary_height_m(50), 35e3, 1e-6);
  const double column = 8000.0 * (1.0 - std::exp(-35e3 / 8000.0));
  for (int i = 0; i < 50; ++i) {
    const double mass = 8000.0 * (std::exp(-kLayers.boundary_height_m(i) / 8000.0) -
                                  std::exp(-kLayers.boundary_height_m(i + 1) / 8000.0));
    EXPECT_NEAR(mass, column / 50.0, 1e-9 * column);
  }
  EXPECT_EQ(kLayers.layer_index(6360e3), 0);
  EXPECT_EQ(kLayers.layer_index(6360e3 - 1e-3), 0);  // clamped, not -1
  EXPECT_EQ(kLayers.layer_index(6360e3 + 34999.0), 49);
  EXPECT_EQ(kLayers.layer_index(
                6360e3 + 0.5 * (kLayers.boundary_height_m(7) + kLayers.boundary_height_m(8))),
            7);
}

TEST(HaberLayers, VerticalOpticalLengthIsTheSumOfTheLayerDensitiesTimesThickness) {
  const Vec3 ground{0.0, 0.0, 6360e3};
  const Vec3 top{0.0, 0.0, 6360e3 + 35e3 - 1.0};
  double expected_rayleigh = 0.0;
  for (int i = 0; i < 50; ++i) {
    const double thickness =
        std::min(kLayers.boundary_height_m(i + 1), 35e3 - 1.0) - kLayers.boundary_height_m(i);
    expected_rayleigh += kLayers.rayleigh_density(i) * thickness;
  }
  const OpticalLength up = optical_length(kLayers, ground, top);
  const OpticalLength down = optical_length(kLayers, top, ground);
  EXPECT_FALSE(up.blocked);
  EXPECT_NEAR(up.rayleigh_m, expected_rayleigh, 1e-6 * expected_rayleigh);
  EXPECT_NEAR(down.rayleigh_m, up.rayleigh_m, 1e-6 * up.rayleigh_m);
  EXPECT_NEAR(down.mie_m, up.mie_m, 1e-6 * up.mie_m);
  // Close to the continuous exponential column (layers hold equal mass, densities at mid-height).
  EXPECT_NEAR(up.rayleigh_m, 8000.0 * (1.0 - std::exp(-35e3 / 8000.0)), 0.01 * 8000.0);
}

TEST(HaberLayers, SegmentsThroughTheEarthAreBlockedAndGrazingOnesAreSplit) {
  // A chord between two points 100 m high and 4 degrees apart dips below the ground.
  const double h = 6360e3 + 100.0;
  const Vec3 a{-h * std::sin(0.0349), 0.0, h * std::cos(0.0349)};
  const Vec3 b{h * std::sin(0.0349), 0.0, h * std::cos(0.0349)};
  EXPECT_TRUE(optical_length(kLayers, a, b).blocked);
  // A horizontal chord at 10 km: its lowest point is in the middle; symmetric halves.
  const double r = 6360e3 + 10e3;
  const Vec3 c{-100e3, 0.0, std::sqrt(r * r - 100e3 * 100e3)};
  const Vec3 d{100e3, 0.0, c.z};
  const OpticalLength whole = optical_length(kLayers, c, d);
  const OpticalLength half = optical_length(kLayers, c, Vec3{0.0, 0.0, c.z});
  EXPECT_FALSE(whole.blocked);
  EXPECT_NEAR(whole.rayleigh_m, 2.0 * half.rayleigh_m, 1e-6 * whole.rayleigh_m);
  EXPECT_GT(whole.rayleigh_m, 0.0);
}

TEST(HaberLayers, ExitPointIsOneMetreBelowTheTop) {
  const Vec3 p{1000.0, 0.0, 6360e3 + 50.0};
  const Vec3 d = normalize(Vec3{0.3, 0.1, 0.5});
  EXPECT_NEAR(length(exit_point(kLayers, p, d)), 6360e3 + 35e3 - 1.0, 1e-6);
}

}  // namespace
}  // namespace clearsky::haber
