// Dome values of the Haber precomputation pinned on the coarse unit-test grid (24 sectors):
// single scattering only and four orders, the sun at 40 degrees and 5 degrees below the
// horizon. Restructuring build_dome must leave them unchanged (they were bit-identical when
// it was split into its phases); the tolerance only allows for a different libm.
#include <gtest/gtest.h>

#include "models/core/numeric.h"
#include "models/haber/haber.h"

namespace clearsky::haber {
namespace {

struct DomeValue {
  int ring;
  int sector;
  std::size_t wavelength;
  double radiance;
};

void expect_dome(int orders, double sun_zenith_deg, std::initializer_list<DomeValue> values) {
  ModelConfig config;
  config.options["azimuth_sectors"] = 24;
  config.options["scattering_orders"] = orders;
  const auto model = HaberModel::create(config);
  const auto state = model->prepare_sun({degrees_to_radians(sun_zenith_deg), 0.0});
  const HaberDome& dome = dynamic_cast<const HaberSunState&>(*state).dome();
  ASSERT_EQ(dome.rings(), 7);
  ASSERT_EQ(dome.sectors(), 12);
  for (const DomeValue& v : values) {
    EXPECT_NEAR(dome.node(v.ring, v.sector)[v.wavelength], v.radiance, 1e-12 * v.radiance)
        << "orders " << orders << " sun zenith " << sun_zenith_deg << " ring " << v.ring
        << " sector " << v.sector << " wavelength " << v.wavelength;
  }
}

TEST(HaberDomeValues, SingleScatteringSunAt40Degrees) {
  expect_dome(1, 40.0,
              {{0, 0, 0, 0.03306574012097073},
               {2, 5, 12, 0.028372032360813086},
               {4, 11, 30, 0.0087860207085571039}});
}

TEST(HaberDomeValues, FourOrdersSunAt40Degrees) {
  expect_dome(4, 40.0,
              {{0, 0, 0, 0.035134918870652378},
               {2, 5, 12, 0.0289430297128953},
               {4, 11, 30, 0.0089434185180594025}});
}

TEST(HaberDomeValues, FourOrdersSunBelowTheHorizon) {
  expect_dome(4, 95.0,
              {{0, 0, 0, 9.5757524359170198e-10},
               {2, 5, 12, 1.3808783017243183e-05},
               {4, 11, 30, 1.2428476165059207e-05}});
}

}  // namespace
}  // namespace clearsky::haber
