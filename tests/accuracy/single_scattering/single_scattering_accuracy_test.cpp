// Nishita93 and O'Neal against the 15 public Kider captures (paper sections "Nishita93 Model",
// "O'Neal Model"; docs/architecture.md "Evaluation against measurements"): the study's code scores
// 26.49 (Nishita93) and 49.75 (O'Neal, 4 samples) mW/(m2.sr.nm) on these captures; we must be
// within 5 %. The paper also reports that O'Neal with 32 samples gives "almost the same results as
// Nishita93": within 2 % per capture.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "models/evaluation/evaluate_model.h"
#include "models/registry.h"
#include "tests/support/public_captures.h"
#include "tests/support/shared_data.h"

namespace clearsky {
namespace {

EvaluationResult evaluate(const char* id, std::map<std::string, double> options = {}) {
  ModelConfig config;
  config.options = std::move(options);
  const ModelFactory* factory = find_model(id);
  if (factory == nullptr) throw std::logic_error(std::string("model not registered: ") + id);
  EvaluationResult r = evaluate_model(*factory, config, testing::public_captures(), {});
  std::printf("%s", id);
  for (const auto& [name, value] : config.options) std::printf(" %s=%g", name.c_str(), value);
  std::printf(": RMSE %.2f (precompute %.3f s, evaluate %.3f s)\n", r.rmse, r.precompute_seconds,
              r.evaluate_seconds);
  for (const auto& c : r.captures) std::printf("  %s  %.2f\n", c.time_iso.c_str(), c.rmse);
  return r;
}

const EvaluationResult& nishita93_result() {
  static const EvaluationResult r = evaluate("nishita93");
  return r;
}

TEST(SingleScatteringAccuracy, Nishita93WithinFivePercentOfTheStudy) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  EXPECT_NEAR(nishita93_result().rmse, 26.49, 0.05 * 26.49);
}

TEST(SingleScatteringAccuracy, Nishita93ReproducesTheStudyWithItsViewerSample) {
  // The study's code started each view ray's trapezoid with a zero integrand at the observer;
  // with that choice the model reproduces the study's 26.49 (the default, the true integrand
  // there, adds the missing half of the lowest layer's light and scores 25.38).
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  EXPECT_NEAR(evaluate("nishita93", {{"study_viewer_sample", 1}}).rmse, 26.49, 0.01);
  EXPECT_NEAR(nishita93_result().rmse, 25.38, 0.01);
}

TEST(SingleScatteringAccuracy, ONealWithinFivePercentOfTheStudy) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  const double rmse = evaluate("oneal").rmse;
  EXPECT_NEAR(rmse, 49.75, 0.05 * 49.75);
  EXPECT_NEAR(rmse, 49.75, 0.01);  // the study's code exactly
}

TEST(SingleScatteringAccuracy, ONealWith32SamplesWithinTwoPercentOfNishita93PerCapture) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  const EvaluationResult oneal = evaluate("oneal", {{"samples", 32}});
  const EvaluationResult& nishita = nishita93_result();
  ASSERT_EQ(oneal.captures.size(), nishita.captures.size());
  for (std::size_t i = 0; i < oneal.captures.size(); ++i) {
    EXPECT_NEAR(oneal.captures[i].rmse / nishita.captures[i].rmse, 1.0, 0.02)
        << oneal.captures[i].time_iso;
  }
}

TEST(SingleScatteringAccuracy, ONealWithTwoSamplesIsWorseThanWithFour) {
  // O'Neil's original 2 samples: the paper reports 57.7 (17 captures) against 49.5 for 4.
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  const double two = evaluate("oneal", {{"samples", 2}}).rmse;
  EXPECT_GT(two, 49.75);
  EXPECT_NEAR(two, 57.7, 0.1 * 57.7);
}

TEST(SingleScatteringAccuracy, CheaperAndFinerSettings) {
  // The error side of the run-time-vs-error curve (tests/bench/single_scattering_bench.cpp
  // gives the run-time side). Nishita93: the paper reports that doubling n_s and n_c changes
  // the RMSE by less than 2 %; O'Neal: more samples, less error (they add the missing light).
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  std::map<int, double> nishita, oneal;
  for (int n : {16, 32, 64, 128})
    nishita[n] = evaluate("nishita93", {{"spheres", n}, {"cylinders", n}}).rmse;
  for (int n : {2, 4, 8, 32}) oneal[n] = evaluate("oneal", {{"samples", n}}).rmse;
  EXPECT_NEAR(nishita[128] / nishita[64], 1.0, 0.02);
  EXPECT_NEAR(nishita[32] / nishita[64], 1.0, 0.05);
  EXPECT_GT(oneal[2], oneal[4]);
  EXPECT_GT(oneal[4], oneal[8]);
  EXPECT_GT(oneal[8], oneal[32]);
}

}  // namespace
}  // namespace clearsky
