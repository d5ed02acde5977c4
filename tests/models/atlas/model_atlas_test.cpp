// The atlas of a model (models/atlas/model_atlas.h), run quick on two models whose builds are
// instant: O'Neal (ray samples converge to the reference) and Preetham (a closed form: its
// reference is its standard setting).
#include "models/atlas/model_atlas.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "models/registry.h"
#include "tests/support/public_captures.h"
#include "tests/support/shared_data.h"

namespace clearsky::atlas {
namespace {

AtlasOptions quick_options() {
  AtlasOptions o;
  o.scope = AtlasScope::quick;
  o.precompute_threads = 1;
  o.min_timing_s = 0.0;
  return o;
}

const SettingMeasurement& named(const ModelAtlasReport& r, const std::string& name) {
  const auto it = std::find_if(r.settings.begin(), r.settings.end(),
                               [&](const SettingMeasurement& m) { return m.setting.name == name; });
  if (it == r.settings.end()) throw std::runtime_error("no setting " + name);
  return *it;
}

TEST(ModelAtlas, MoreRaySamplesComeCloserToTheReference) {
  const ModelFactory* f = find_model("oneal");
  ASSERT_NE(f, nullptr);
  const ModelAtlasReport r = model_atlas(*f, quick_options());
  EXPECT_EQ(r.settings.front().setting.name, "standard");
  const SettingMeasurement& two = named(r, "samples=2");
  const SettingMeasurement& four = named(r, "standard");
  const SettingMeasurement& sixteen = named(r, "samples=16");
  EXPECT_GT(two.spectral_error.count, 10u);
  EXPECT_EQ(two.samples_refused, 0u);
  EXPECT_GT(two.spectral_error.p95, four.spectral_error.p95);
  EXPECT_GT(four.spectral_error.p95, sixteen.spectral_error.p95);
  EXPECT_GT(sixteen.spectral_error.p95, 0.0);
  EXPECT_GE(two.spectral_error.max, two.spectral_error.p95);
  EXPECT_GE(two.spectral_error.p95, two.spectral_error.median);
  EXPECT_GT(four.radiance_s, 0.0);
  EXPECT_GT(four.batch_81_s, four.radiance_s);
  EXPECT_FALSE(r.pareto_build.empty());
  EXPECT_FALSE(r.pareto_query.empty());
  // The draft is the cheapest within 2%, so no cheaper setting is within 2%.
  if (!r.draft.empty()) {
    const SettingMeasurement& draft = named(r, r.draft);
    EXPECT_LE(draft.spectral_error.p95, kDraftMaxP95Error);
    for (const SettingMeasurement& m : r.settings) {
      if (m.first_sky_s() < draft.first_sky_s()) {
        EXPECT_GT(m.spectral_error.p95, kDraftMaxP95Error) << m.setting.name;
      }
    }
  }
}

TEST(ModelAtlas, AClosedFormIsItsOwnReferenceAndThreeWavelengthsCostColour) {
  const ModelFactory* f = find_model("preetham");
  ASSERT_NE(f, nullptr);
  const ModelAtlasReport r = model_atlas(*f, quick_options());
  EXPECT_FALSE(r.reference_check.has_value());
  const SettingMeasurement& standard = named(r, "standard");
  EXPECT_EQ(standard.spectral_error.max, 0.0);
  EXPECT_EQ(standard.luminance_error.max, 0.0);
  EXPECT_FALSE(r.draft.empty());
  const SettingMeasurement& rgb = named(r, "rgb");
  EXPECT_EQ(rgb.wavelengths, 3u);
  EXPECT_GT(rgb.spectral_error.p95, 0.0);
  EXPECT_GT(rgb.luminance_error.max, 0.0);
}

// The atlas's RMSE is the study's: the standard setting gives what `clearsky evaluate` gives.
TEST(ModelAtlas, TheStandardSettingsRmseIsTheEvaluationsRmse) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014");
  const ModelFactory* f = find_model("preetham");
  ASSERT_NE(f, nullptr);
  AtlasOptions o = quick_options();
  o.captures = testing::public_captures();
  const ModelAtlasReport r = model_atlas(*f, o);
  const EvaluationResult e = evaluate_model(*f, ModelConfig{}, testing::public_captures());
  ASSERT_TRUE(named(r, "standard").rmse.has_value());
  EXPECT_EQ(*named(r, "standard").rmse, e.rmse);
  EXPECT_EQ(named(r, "standard").rmse_wavelengths, e.wavelengths_nm.size());
  EXPECT_EQ(named(r, "rgb").rmse_wavelengths, 3u);
}

}  // namespace
}  // namespace clearsky::atlas
