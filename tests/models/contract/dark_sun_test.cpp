// Dark suns (docs/model-contract.md "Dark suns"), checked on every registered model that declares
// capabilities.dark_beyond_sun_zenith_deg: just beyond it, the full computation (the per-sun
// state prepared in full) answers exactly zero everywhere in the declared domain, and the fast
// path answers the same zeros without preparing any per-sun state.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "models/core/numeric.h"
#include "models/registry.h"
#include "tests/models/support/cheap_model_config.h"

namespace clearsky {
namespace {

double deg(double degrees) { return degrees_to_radians(degrees); }

std::vector<const ModelFactory*> declaring_darkness() {
  std::vector<const ModelFactory*> out;
  for (const ModelFactory& f : registered_models())
    if (f.descriptor->capabilities.dark_beyond_sun_zenith_deg.has_value()) out.push_back(&f);
  return out;
}

// Views over the answered sky, denser towards the horizon and the sun's azimuth (0 here), where
// the last light of twilight stays longest.
std::vector<ViewDirection> dark_views(const ModelCapabilities& c) {
  std::vector<ViewDirection> views;
  const double last = c.view_below_horizon ? 180.0 : 90.0;
  for (double z = 0.0; z <= last + 1e-9; z += 10.0)
    for (double a = 0.0; a < 360.0; a += 30.0) views.push_back({deg(z), deg(a)});
  for (double z : {80.0, 85.0, 88.0, 89.5, 89.9})
    for (double a : {0.0, 2.5, 5.0, 10.0, 20.0}) views.push_back({deg(z), deg(a)});
  return views;
}

std::vector<double> dark_altitudes_m(const ModelCapabilities& c) {
  std::vector<double> h = {c.min_altitude_m};
  for (double x : {1000.0, 10e3, 30e3})
    if (x > c.min_altitude_m && x < c.max_altitude_m) h.push_back(x);
  if (c.max_altitude_m > c.min_altitude_m) h.push_back(c.max_altitude_m);
  return h;
}

// Suns just beyond the declared zenith, and one deep in the night.
std::vector<double> dark_suns_deg(const ModelCapabilities& c) {
  const double threshold = *c.dark_beyond_sun_zenith_deg;
  std::vector<double> out;
  for (double beyond : {0.01, 0.5, 2.0, 49.0})
    if (threshold + beyond <= c.max_sun_zenith_deg) out.push_back(threshold + beyond);
  return out;
}

// The configurations checked: the cheap one, and the coarsest the descriptor allows (every
// integer option at its minimum: fewest table nodes, sectors, spheres; the widest
// sun_zenith_bucket_deg, whose state serves suns up to half its width away).
std::vector<ModelConfig> dark_configs(const ModelDescriptor& d) {
  ModelConfig coarsest = testing::cheap_config(d);
  for (const ParameterSpec& p : d.parameters) {
    if (p.atmosphere) continue;
    if (p.integer) coarsest.options[p.name] = p.min_value;
    if (p.name == "sun_zenith_bucket_deg") coarsest.options[p.name] = p.max_value;
  }
  return {testing::cheap_config(d), coarsest};
}

class DarkSun : public ::testing::TestWithParam<const ModelFactory*> {
 protected:
  const ModelFactory& factory() const { return *GetParam(); }
};

TEST_P(DarkSun, TheDeclaredZenithLiesInsideTheSunsAnswered) {
  const ModelCapabilities& c = factory().descriptor->capabilities;
  // Beyond the geometric sunset of the ground at least, and short of the last sun answered.
  EXPECT_GT(*c.dark_beyond_sun_zenith_deg, 90.0);
  EXPECT_LT(*c.dark_beyond_sun_zenith_deg, c.max_sun_zenith_deg);
}

// The full computation (the per-sun state prepared in full) answers zeros just beyond the
// declared zenith, over views, altitudes, sun and sky irradiance.
void expect_dark_beyond_the_declared_zenith(const SkyModel& model) {
  const ModelCapabilities& c = model.descriptor().capabilities;
  const std::vector<ViewDirection> views = dark_views(c);
  PrecomputeContext full;
  full.dark_sun_at_once = false;
  for (double sun_zenith : dark_suns_deg(c)) {
    const auto state = model.prepare_sun({deg(sun_zenith), deg(0.0)}, full);
    ASSERT_FALSE(state->dark());
    for (double altitude : dark_altitudes_m(c)) {
      SpectralBatch out;
      model.sky_radiance(*state, {altitude}, views, out);
      for (std::size_t i = 0; i < views.size(); ++i) {
        ASSERT_EQ(out.status[i], SampleStatus::ok);
        for (double v : out.spectrum(i)) {
          ASSERT_EQ(v, 0.0) << model.descriptor().id << " sun " << sun_zenith << " altitude "
                            << altitude << " view " << radians_to_degrees(views[i].zenith_rad)
                            << ", " << radians_to_degrees(views[i].azimuth_rad);
        }
      }
      for (const SpectralSample& s :
           {model.sun_irradiance(*state, {altitude}), model.sky_irradiance(*state, {altitude}),
            model.sky_irradiance(*state, {altitude}, {deg(90.0), deg(0.0)})}) {
        ASSERT_EQ(s.status, SampleStatus::ok);
        for (double v : s.value)
          ASSERT_EQ(v, 0.0) << "irradiance, sun " << sun_zenith << " altitude " << altitude;
      }
    }
  }
}

TEST_P(DarkSun, TheFullComputationIsExactlyZeroBeyondTheDeclaredZenith) {
  for (const ModelConfig& config : dark_configs(*factory().descriptor)) {
    SCOPED_TRACE(config.canonical_string());
    expect_dark_beyond_the_declared_zenith(*factory().create(config, {}));
  }
}

TEST_P(DarkSun, ADarkSunIsAnsweredWithoutPreparingAnything) {
  // A model of its own, so that its per-sun counter starts at zero.
  const auto model = factory().create(testing::cheap_config(*factory().descriptor), {});
  const ModelCapabilities& c = model->descriptor().capabilities;
  const std::vector<ViewDirection> views = dark_views(c);
  for (double sun_zenith : dark_suns_deg(c)) {
    const SunPosition sun{deg(sun_zenith), deg(30.0)};
    ASSERT_TRUE(model->sun_is_dark(sun));
    const auto state = model->prepare_sun(sun);
    EXPECT_TRUE(state->dark());
    for (double altitude : dark_altitudes_m(c)) {
      SpectralBatch out;
      model->sky_radiance(*state, {altitude}, views, out);
      for (std::size_t i = 0; i < views.size(); ++i) {
        ASSERT_EQ(out.status[i], SampleStatus::ok);
        for (double v : out.spectrum(i)) ASSERT_EQ(v, 0.0);
      }
      for (const SpectralSample& s :
           {model->sun_irradiance(*state, {altitude}), model->sky_irradiance(*state, {altitude})}) {
        ASSERT_EQ(s.status, SampleStatus::ok);
        for (double v : s.value) ASSERT_EQ(v, 0.0);
      }
    }
  }
  // Refusals still come first: a view the model does not answer is refused, not zero.
  if (!c.view_below_horizon) {
    const auto state = model->prepare_sun({deg(dark_suns_deg(c).front()), 0.0});
    SpectralBatch out;
    const std::vector<ViewDirection> below = {{deg(120.0), 0.0}};
    model->sky_radiance(*state, {c.min_altitude_m}, below, out);
    EXPECT_EQ(out.status[0], SampleStatus::view_below_horizon_unsupported);
  }
  EXPECT_EQ(model->sun_states_built(), 0u);
  // The counter counts: a lit sun is prepared (for a model with per-sun precomputation).
  const auto lit = model->prepare_sun({deg(60.0), 0.0});
  EXPECT_FALSE(lit->dark());
  EXPECT_FALSE(model->sun_is_dark({deg(*c.dark_beyond_sun_zenith_deg), 0.0}));
  if (c.per_sun_precomputation) {
    EXPECT_EQ(model->sun_states_built(), 1u);
  }
}

INSTANTIATE_TEST_SUITE_P(Registered, DarkSun, ::testing::ValuesIn(declaring_darkness()),
                         [](const ::testing::TestParamInfo<const ModelFactory*>& param) {
                           return param.param->descriptor->id;
                         });

}  // namespace
}  // namespace clearsky
