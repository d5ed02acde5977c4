// RMSE of the per-sun models (Haber, Nishita96) on the 15 public captures of 2013-05-27 against the
// study's code (docs/architecture.md "Evaluation against measurements"): Haber 14.80 (paper 14.7 on
// 17 captures). Each capture builds one per-sun state (about a second each for Haber on 2 cores),
// so the test runs the full precomputation 15 times.
#include <gtest/gtest.h>

#include <cstdio>

#include "models/evaluation/evaluate_model.h"
#include "models/registry.h"
#include "tests/support/public_captures.h"
#include "tests/support/shared_data.h"

namespace clearsky {
namespace {

TEST(PerSunAccuracy, HaberMatchesTheStudyOnThe15PublicCaptures) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  const ModelFactory* factory = find_model("haber");
  ASSERT_NE(factory, nullptr);
  EvaluationOptions options;
  options.capture_threads = 1;  // each per-sun build already uses every core
  // The default shares one dome per degree of sun zenith (measured 14.770; exact angles, the
  // study's setting, 14.796): both within 5% of the study's 14.80, and the bucket costs < 0.5%.
  const EvaluationResult r =
      evaluate_model(*factory, ModelConfig{}, testing::public_captures(), options);
  for (const auto& c : r.captures)
    std::printf("haber %s zenith %.3f rmse %.3f\n", c.time_iso.c_str(), c.sun_zenith_deg, c.rmse);
  std::printf("haber total rmse %.3f, evaluate %.1f s\n", r.rmse, r.evaluate_seconds);
  EXPECT_NEAR(r.rmse, 14.80, 0.05 * 14.80);
  EXPECT_NEAR(r.rmse, 14.796, 0.005 * 14.796);
}

}  // namespace
}  // namespace clearsky

namespace clearsky {
namespace {

// Nishita96 with the nearest-direction binning done right: the study's code fixed the same way
// scores 11.09 (with its indexing bug 18.06; the paper, 17 captures, 18.3).
TEST(PerSunAccuracy, Nishita96MatchesTheStudyWithTheBinningFixed) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  const ModelFactory* factory = find_model("nishita96");
  ASSERT_NE(factory, nullptr);
  const EvaluationResult r =
      evaluate_model(*factory, ModelConfig{}, testing::public_captures(), {});
  for (const auto& c : r.captures)
    std::printf("nishita96 %s rmse %.3f\n", c.time_iso.c_str(), c.rmse);
  std::printf("nishita96 total rmse %.3f, evaluate %.1f s\n", r.rmse, r.evaluate_seconds);
  EXPECT_NEAR(r.rmse, 11.09, 0.05 * 11.09);
}

}  // namespace
}  // namespace clearsky

namespace clearsky {
namespace {

// The accuracy cost of sharing per-sun tables within a sun-zenith bucket: only the double
// scattering uses the bucket's zenith. Measured: 11.088 (0.5 deg), 11.088 (1), 11.078 (2),
// 11.089 (5) against 11.090 exact.
TEST(PerSunAccuracy, Nishita96SunZenithBucketsCostNothingMeasurable) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  const ModelFactory* factory = find_model("nishita96");
  ASSERT_NE(factory, nullptr);
  const EvaluationResult exact =
      evaluate_model(*factory, ModelConfig{}, testing::public_captures(), {});
  for (double bucket : {1.0, 5.0}) {
    ModelConfig config;
    config.options["sun_zenith_bucket_deg"] = bucket;
    const EvaluationResult r = evaluate_model(*factory, config, testing::public_captures(), {});
    std::printf("nishita96 bucket %.1f deg: rmse %.3f (exact %.3f)\n", bucket, r.rmse, exact.rmse);
    EXPECT_NEAR(r.rmse, exact.rmse, 0.05);
  }
}

}  // namespace
}  // namespace clearsky
