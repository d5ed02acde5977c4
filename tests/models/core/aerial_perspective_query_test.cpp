// The checked aerial-perspective query of SkyModel: refused without the capability or with a
// bad distance, statuses from the sun/viewpoint/view checks, values passed through otherwise.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "models/core/sky_model.h"

namespace clearsky {
namespace {

ModelDescriptor haze_descriptor(bool aerial_perspective) {
  ModelDescriptor d;
  d.id = "haze-test";
  d.version = "1";
  d.min_wavelength_nm = 300;
  d.max_wavelength_nm = 700;
  d.capabilities.max_altitude_m = 1000.0;
  d.capabilities.aerial_perspective = aerial_perspective;
  return d;
}

// A homogeneous haze: transmittance exp(-d / 1 km), in-scattered radiance 1 - that.
class HazeModel final : public SkyModel {
 public:
  HazeModel(ModelDescriptor d, double poison = 0.0)
      : SkyModel(config()), descriptor_(std::move(d)), poison_(poison) {}
  const ModelDescriptor& descriptor() const override { return descriptor_; }

 protected:
  void compute_sky_radiance(const SunState&, const Viewpoint&, std::span<const ViewDirection>,
                            SpectralBatch&) const override {}
  Spectrum compute_sun_irradiance(const SunState&, const Viewpoint&) const override {
    return Spectrum(3, 1.0);
  }
  ScatteringAlongRay compute_aerial_perspective(const SunState&, const Viewpoint&,
                                                const ViewDirection&,
                                                double distance_m) const override {
    const double t = std::exp(-distance_m / 1000.0);
    return {Spectrum(3, 1.0 - t + poison_), Spectrum(3, t), distance_m, false};
  }

 private:
  static ModelConfig config() {
    ModelConfig c;
    c.wavelengths = WavelengthGrid::points({400.0, 500.0, 800.0});
    return c;
  }
  ModelDescriptor descriptor_;
  double poison_;
};

TEST(AerialPerspectiveQuery, PassesValuesAndZeroesWavelengthsOutOfRange) {
  const HazeModel model(haze_descriptor(true));
  const SunState sun(SunPosition{0.3, 1.0});
  const auto s = model.aerial_perspective(sun, {10.0}, {1.2, 0.5}, 1000.0);
  ASSERT_EQ(s.status, SampleStatus::ok);
  EXPECT_DOUBLE_EQ(s.transmittance[0], std::exp(-1.0));
  EXPECT_DOUBLE_EQ(s.radiance[1], 1.0 - std::exp(-1.0));
  EXPECT_EQ(s.radiance[2], 0.0);  // 800 nm is outside 300..700 nm
}

TEST(AerialPerspectiveQuery, RefusedWithoutTheCapabilityOrWithABadDistance) {
  const SunState sun(SunPosition{0.3, 1.0});
  EXPECT_EQ(
      HazeModel(haze_descriptor(false)).aerial_perspective(sun, {0.0}, {1.0, 0.0}, 10.0).status,
      SampleStatus::invalid_input);
  const HazeModel model(haze_descriptor(true));
  for (double d :
       {-1.0, std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity()}) {
    EXPECT_EQ(model.aerial_perspective(sun, {0.0}, {1.0, 0.0}, d).status,
              SampleStatus::invalid_input)
        << d;
  }
  // +infinity asks for the whole view (to the ground or the top of the atmosphere).
  EXPECT_EQ(
      model.aerial_perspective(sun, {0.0}, {1.0, 0.0}, std::numeric_limits<double>::infinity())
          .status,
      SampleStatus::ok);
  EXPECT_EQ(model.aerial_perspective(sun, {2000.0}, {1.0, 0.0}, 10.0).status,
            SampleStatus::viewpoint_unsupported);
  EXPECT_EQ(model.aerial_perspective(sun, {0.0}, {2.0, 0.0}, 10.0).status,
            SampleStatus::view_below_horizon_unsupported);
  EXPECT_EQ(
      model.aerial_perspective(SunState(SunPosition{2.0, 0.0}), {0.0}, {1.0, 0.0}, 10.0).status,
      SampleStatus::sun_below_horizon_unsupported);
}

TEST(AerialPerspectiveQuery, NegativeRadianceNeverLeaves) {
  const HazeModel model(haze_descriptor(true), -5.0);
  const auto s = model.aerial_perspective(SunState(SunPosition{0.3, 1.0}), {0.0}, {1.0, 0.0}, 10.0);
  EXPECT_EQ(s.status, SampleStatus::numerical_failure);
  for (double v : s.radiance) EXPECT_EQ(v, 0.0);
}

}  // namespace
}  // namespace clearsky
