// The checks around model queries, with a test model of known answers: a uniform sky of radiance L
// gives irradiance pi L on a horizontal plane (docs/conventions.md "Physical identities"), statuses
// are set before computing, and bad values never leave a query.
#include "models/core/sky_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace clearsky {
namespace {

ModelDescriptor uniform_descriptor(double max_sun_zenith_deg, bool below_horizon) {
  ModelDescriptor d;
  d.id = "uniform-test";
  d.version = "1";
  d.min_wavelength_nm = 300;
  d.max_wavelength_nm = 700;
  d.capabilities.max_sun_zenith_deg = max_sun_zenith_deg;
  d.capabilities.view_below_horizon = below_horizon;
  d.parameters = {{"level", "W/(m2.sr.nm)", "radiance", 1.0, 0.0, 10.0, false, false}};
  return d;
}

// Radiance `level` everywhere, or a poisoned value for views with zenith exactly 0.5 rad; views
// with zenith exactly 0.7 rad are refused by the model itself (outside_fit_domain, as a fitted
// model does), their values left as computed.
class UniformSky final : public SkyModel {
 public:
  UniformSky(ModelConfig c, ModelDescriptor d, double poison = 0.0)
      : SkyModel(std::move(c)), descriptor_(std::move(d)), poison_(poison) {}
  const ModelDescriptor& descriptor() const override { return descriptor_; }
  mutable int computed_views = 0;  // test instrumentation only

 protected:
  void compute_sky_radiance(const SunState&, const Viewpoint&, std::span<const ViewDirection> views,
                            SpectralBatch& out) const override {
    computed_views += static_cast<int>(views.size());
    const double level = option_or_default(descriptor_, config(), "level");
    for (std::size_t i = 0; i < views.size(); ++i) {
      for (double& v : out.spectrum(i)) v = views[i].zenith_rad == 0.5 ? poison_ : level;
      if (views[i].zenith_rad == 0.7) out.status[i] = SampleStatus::outside_fit_domain;
    }
  }
  Spectrum compute_sun_irradiance(const SunState&, const Viewpoint&) const override {
    return Spectrum(wavelengths().size(), 1.0);
  }

 private:
  ModelDescriptor descriptor_;
  double poison_;
};

ModelConfig small_config() {
  ModelConfig c;
  c.wavelengths = WavelengthGrid::points({400.0, 500.0, 800.0});
  c.options["level"] = 2.0;
  return c;
}

TEST(SkyModel, UniformSkyGivesPiLOnAHorizontalPlane) {
  const UniformSky sky(small_config(), uniform_descriptor(90, false));
  const auto sun = sky.prepare_sun({0.3, 1.0});
  const SpectralSample e = sky.sky_irradiance(*sun, {});
  ASSERT_EQ(e.status, SampleStatus::ok);
  EXPECT_NEAR(e.value[0], kPi * 2.0, 1e-10);
  EXPECT_EQ(e.value[2], 0.0) << "800 nm is outside the model's range";
  EXPECT_FALSE(sky.answers_wavelength(2));
}

TEST(SkyModel, VerticalPlaneSeesHalfTheUniformSkyWhenTheGroundIsNotAnswered) {
  const UniformSky sky(small_config(), uniform_descriptor(90, false));
  const auto sun = sky.prepare_sun({0.3, 1.0});
  const SpectralSample e = sky.sky_irradiance(*sun, {}, {kPi / 2, 0.0});
  ASSERT_EQ(e.status, SampleStatus::ok);
  EXPECT_NEAR(e.value[0], kPi * 2.0 / 2.0, 0.02);
  const UniformSky everywhere(small_config(), uniform_descriptor(90, true));
  const SpectralSample full = everywhere.sky_irradiance(*sun, {}, {kPi / 2, 0.0});
  EXPECT_NEAR(full.value[0], kPi * 2.0, 1e-9);
}

TEST(SkyModel, RefusesTheSunBelowTheModelsLimitBeforeComputing) {
  const UniformSky sky(small_config(), uniform_descriptor(90, false));
  EXPECT_EQ(sky.check_sun({degrees_to_radians(95.0), 0.0}),
            SampleStatus::sun_below_horizon_unsupported);
  EXPECT_THROW(sky.prepare_sun({degrees_to_radians(95.0), 0.0}), std::invalid_argument);
  EXPECT_EQ(sky.check_sun({std::numeric_limits<double>::quiet_NaN(), 0.0}),
            SampleStatus::invalid_input);
}

TEST(SkyModel, SetsAStatusPerViewAndComputesOnlyAnswerableViews) {
  const UniformSky sky(small_config(), uniform_descriptor(90, false));
  const auto sun = sky.prepare_sun({0.3, 1.0});
  const std::vector<ViewDirection> views = {
      {0.2, 0.0}, {2.0, 0.0}, {std::numeric_limits<double>::quiet_NaN(), 0.0}, {1.0, 3.0}};
  SpectralBatch out;
  sky.sky_radiance(*sun, {}, views, out);
  EXPECT_EQ(out.status[0], SampleStatus::ok);
  EXPECT_EQ(out.status[1], SampleStatus::view_below_horizon_unsupported);
  EXPECT_EQ(out.status[2], SampleStatus::invalid_input);
  EXPECT_EQ(out.status[3], SampleStatus::ok);
  EXPECT_EQ(sky.computed_views, 2);
  EXPECT_EQ(out.spectrum(1)[0], 0.0);
  EXPECT_EQ(out.spectrum(3)[1], 2.0);
}

TEST(SkyModel, NonFiniteOrNegativeValuesNeverLeaveAQuery) {
  for (double poison :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), -1.0}) {
    const UniformSky sky(small_config(), uniform_descriptor(90, false), poison);
    const auto sun = sky.prepare_sun({0.3, 1.0});
    const std::vector<ViewDirection> views = {{0.5, 0.0}, {0.6, 0.0}};
    SpectralBatch out;
    sky.sky_radiance(*sun, {}, views, out);
    EXPECT_EQ(out.status[0], SampleStatus::numerical_failure) << poison;
    EXPECT_EQ(out.spectrum(0)[0], 0.0);
    EXPECT_EQ(out.status[1], SampleStatus::ok);
  }
}

TEST(SkyModel, TheCheckOfTheAnswersSortsEveryKindOfValue) {
  // The usual spectrum passes an integer test of the bit patterns; anything else (a negative
  // value, -0, infinity, NaN) goes through the floating checks.
  struct Case {
    double value;
    SampleStatus status;
    double answered;
  };
  const double largest = std::numeric_limits<double>::max();
  const double tiny = std::numeric_limits<double>::denorm_min();
  for (const Case& c :
       {Case{largest, SampleStatus::ok, largest}, Case{tiny, SampleStatus::ok, tiny},
        Case{0.0, SampleStatus::ok, 0.0}, Case{-0.0, SampleStatus::ok, 0.0},
        Case{-1e-310, SampleStatus::ok, 0.0},
        Case{-std::numeric_limits<double>::infinity(), SampleStatus::numerical_failure, 0.0},
        Case{-std::numeric_limits<double>::quiet_NaN(), SampleStatus::numerical_failure, 0.0},
        Case{-largest, SampleStatus::numerical_failure, 0.0}}) {
    const UniformSky sky(small_config(), uniform_descriptor(90, false), c.value);
    const auto sun = sky.prepare_sun({0.3, 1.0});
    const std::vector<ViewDirection> views = {{0.5, 0.0}};
    SpectralBatch out;
    sky.sky_radiance(*sun, {}, views, out);
    EXPECT_EQ(out.status[0], c.status) << c.value;
    EXPECT_EQ(out.spectrum(0)[0], c.answered) << c.value;
  }
}

TEST(SkyModel, ABatchOfUsualSpectraKeepsItsValuesAndClearsTheViewsTheModelRefused) {
  // Every value finite and positive: the whole batch is checked in one pass; a view the model
  // refused still answers zeros, and a wavelength outside the model's range is still 0.
  ModelConfig in_range = small_config();
  in_range.wavelengths = WavelengthGrid::points({400.0, 500.0, 600.0});
  for (const ModelConfig& config : {in_range, small_config()}) {
    const UniformSky sky(config, uniform_descriptor(90, false));
    const auto sun = sky.prepare_sun({0.3, 1.0});
    const std::vector<ViewDirection> views = {{0.2, 0.0}, {0.7, 1.0}, {1.0, 3.0}};
    SpectralBatch out;
    for (int repeat = 0; repeat < 2; ++repeat) {  // the same batch again: nothing stale
      sky.sky_radiance(*sun, {}, views, out);
      ASSERT_EQ(out.size(), 3u);
      EXPECT_EQ(out.status[0], SampleStatus::ok);
      EXPECT_EQ(out.status[1], SampleStatus::outside_fit_domain);
      EXPECT_EQ(out.status[2], SampleStatus::ok);
      for (std::size_t w = 0; w < 3; ++w) {
        const bool answered = w < 2 || config.wavelengths[2] < 700.0;
        EXPECT_EQ(out.spectrum(0)[w], answered ? 2.0 : 0.0) << w;
        EXPECT_EQ(out.spectrum(1)[w], 0.0) << w;
        EXPECT_EQ(out.spectrum(2)[w], answered ? 2.0 : 0.0) << w;
      }
    }
  }
}

TEST(SkyModel, ViewpointOutsideTheAltitudeRangeIsRefused) {
  const UniformSky sky(small_config(), uniform_descriptor(90, false));
  const auto sun = sky.prepare_sun({0.3, 1.0});
  SpectralBatch out;
  const std::vector<ViewDirection> views = {{0.2, 0.0}};
  sky.sky_radiance(*sun, {1000.0}, views, out);
  EXPECT_EQ(out.status[0], SampleStatus::viewpoint_unsupported);
  EXPECT_EQ(sky.sun_irradiance(*sun, {1000.0}).status, SampleStatus::viewpoint_unsupported);
}

TEST(ModelConfig, ValidationNamesUnknownAndOutOfRangeOptions) {
  const ModelDescriptor d = uniform_descriptor(90, false);
  ModelConfig c = small_config();
  EXPECT_NO_THROW(validate_config(d, c));
  c.options["levl"] = 1.0;
  EXPECT_THROW(validate_config(d, c), std::invalid_argument);
  c = small_config();
  c.options["level"] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(validate_config(d, c), std::invalid_argument);
  EXPECT_NE(small_config().canonical_string(), ModelConfig{}.canonical_string());
}

}  // namespace
}  // namespace clearsky
