// Per-sample errors on the 15 public captures (models/evaluation/evaluate_model.h): they
// recompute every capture's RMSE, and their bias shows the paper's findings (Bruneton 2016,
// "Quantitative evaluation" of each model): Preetham overestimates the measured values (by a
// factor of about 2), O'Neal underestimates them (by a factor of about 3), direction by
// direction and not only on average.
#include <gtest/gtest.h>

#include <cmath>

#include "models/evaluation/evaluate_model.h"
#include "models/registry.h"
#include "tests/support/public_captures.h"
#include "tests/support/shared_data.h"

namespace clearsky {
namespace {

struct BiasSummary {
  double mean = 0;
  int positive = 0;
  int negative = 0;
};

BiasSummary bias_of(const CaptureEvaluation& capture) {
  BiasSummary b;
  for (const SampleEvaluation& s : capture.samples) {
    b.mean += s.bias / static_cast<double>(capture.samples.size());
    b.positive += s.bias > 0 ? 1 : 0;
    b.negative += s.bias < 0 ? 1 : 0;
  }
  return b;
}

void expect_samples_recompute_capture_rmse(const EvaluationResult& r) {
  ASSERT_EQ(r.wavelengths_nm.size(), 31u);
  for (const CaptureEvaluation& c : r.captures) {
    ASSERT_EQ(c.samples.size(), 81u) << c.label;
    double squares = 0;
    for (const SampleEvaluation& s : c.samples) squares += s.rmse * s.rmse;
    EXPECT_NEAR(std::sqrt(squares / 81.0) / c.rmse, 1.0, 1e-9) << r.model_id << " " << c.label;
  }
}

TEST(PerSampleErrorsAccuracy, PreethamOverestimatesAndONealUnderestimatesEverywhere) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  const EvaluationResult preetham =
      evaluate_model(*find_model("preetham"), ModelConfig{}, testing::public_captures(), {});
  const EvaluationResult oneal =
      evaluate_model(*find_model("oneal"), ModelConfig{}, testing::public_captures(), {});
  expect_samples_recompute_capture_rmse(preetham);
  expect_samples_recompute_capture_rmse(oneal);
  ASSERT_EQ(preetham.captures.size(), 15u);
  for (std::size_t i = 0; i < preetham.captures.size(); ++i) {
    // Measured here: Preetham +73 to +81 mW/(m2.sr.nm) on average, 80 or 81 of the 81
    // directions too bright; O'Neal -38 to -41, all 81 too dark.
    const BiasSummary p = bias_of(preetham.captures[i]);
    EXPECT_GT(p.mean, 60.0) << preetham.captures[i].label;
    EXPECT_GE(p.positive, 78) << preetham.captures[i].label;
    const BiasSummary o = bias_of(oneal.captures[i]);
    EXPECT_LT(o.mean, -30.0) << oneal.captures[i].label;
    EXPECT_GE(o.negative, 78) << oneal.captures[i].label;
    // The bias cannot exceed the RMSE of the same values.
    for (const SampleEvaluation& s : preetham.captures[i].samples)
      EXPECT_LE(std::abs(s.bias), s.rmse * (1 + 1e-12));
  }
}

}  // namespace
}  // namespace clearsky
