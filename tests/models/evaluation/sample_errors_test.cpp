// Tests of the per-sample errors of an evaluation (models/evaluation/evaluate_model.h): they
// recompute the capture's RMSE, carry the sign of the model's error, and keep the error at each
// compared wavelength, against test models whose error is known by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "models/evaluation/evaluate_model.h"
#include "tests/models/evaluation/function_model.h"
#include "tests/models/evaluation/synthetic_sky.h"

namespace clearsky {
namespace {

using testing::FunctionModel;

double sky(const ViewDirection& view, double nm) {
  return 0.05 + 0.02 * std::cos(view.zenith_rad) + 0.01 * std::sin(view.azimuth_rad) +
         1e-5 * (nm - 500);
}

// An error that changes with direction and wavelength (and sign), W/(m2.sr.nm).
double uneven_error(const ViewDirection& view, double nm) {
  return 0.004 * std::sin(3.0 * view.azimuth_rad + 0.1 * nm) * std::cos(view.zenith_rad) +
         0.001 * view.zenith_rad;
}

TEST(SampleErrors, SamplesRecomputeTheCaptureRmse) {
  const std::vector<MeasuredCapture> captures = {testing::synthetic_capture(sky, 40.0, 120.0),
                                                 testing::synthetic_capture(sky, 30.0, 150.0)};
  const FunctionModel model(
      [](const ViewDirection& v, double nm) { return sky(v, nm) + uneven_error(v, nm); });
  const EvaluationResult r = evaluate_sky_model(model, captures);
  ASSERT_EQ(r.wavelengths_nm.size(), 31u);
  for (const CaptureEvaluation& c : r.captures) {
    ASSERT_EQ(c.samples.size(), 81u);
    ASSERT_EQ(c.sample_errors.size(), 81u * 31u);
    double sum_squares = 0;
    for (const SampleEvaluation& s : c.samples) sum_squares += s.rmse * s.rmse;
    const double recomputed = std::sqrt(sum_squares / static_cast<double>(c.samples.size()));
    EXPECT_GT(c.rmse, 0.5);
    EXPECT_NEAR(recomputed / c.rmse, 1.0, 1e-9);
  }
}

TEST(SampleErrors, EachSampleKeepsItsDirectionAndSpectralErrors) {
  const std::vector<MeasuredCapture> captures = {testing::synthetic_capture(sky)};
  const FunctionModel model(
      [](const ViewDirection& v, double nm) { return sky(v, nm) + uneven_error(v, nm); });
  const EvaluationResult r = evaluate_sky_model(model, captures);
  const CaptureEvaluation& c = r.captures[0];
  for (std::size_t s = 0; s < c.samples.size(); ++s) {
    const MeasuredSample& measured = captures[0].samples[s];
    const SampleEvaluation& e = c.samples[s];
    EXPECT_EQ(e.index, measured.index);
    EXPECT_DOUBLE_EQ(e.view_zenith_deg, measured.view.zenith_rad * 180.0 / kPi);
    EXPECT_DOUBLE_EQ(e.view_azimuth_deg, measured.view.azimuth_rad * 180.0 / kPi);
    const auto errors = c.errors_of(s);
    ASSERT_EQ(errors.size(), r.wavelengths_nm.size());
    double sum = 0;
    double squares = 0;
    for (std::size_t k = 0; k < errors.size(); ++k) {
      // The synthetic sky is linear in wavelength between its 1-nm samples: the interpolated
      // measurement is exact, so the error is the model's by construction (mW).
      EXPECT_NEAR(errors[k], 1000.0 * uneven_error(measured.view, r.wavelengths_nm[k]), 1e-9);
      sum += errors[k];
      squares += errors[k] * errors[k];
    }
    EXPECT_NEAR(e.bias, sum / 31.0, 1e-12);
    EXPECT_NEAR(e.rmse, std::sqrt(squares / 31.0), 1e-12);
  }
  // The capture's order, which is the synthetic layout's scan order 0..80.
  EXPECT_EQ(c.samples.front().index, 0);
  EXPECT_EQ(c.samples.back().index, 80);
}

TEST(SampleErrors, BiasIsModelMinusMeasured) {
  const std::vector<MeasuredCapture> captures = {testing::synthetic_capture(sky)};
  // A model 3 mW too bright everywhere, and one 2.5 mW too dark.
  const FunctionModel bright([](const ViewDirection& v, double nm) { return sky(v, nm) + 0.003; });
  const FunctionModel dark([](const ViewDirection& v, double nm) { return sky(v, nm) - 0.0025; });
  const EvaluationResult over = evaluate_sky_model(bright, captures);
  const EvaluationResult under = evaluate_sky_model(dark, captures);
  for (std::size_t s = 0; s < 81; ++s) {
    EXPECT_NEAR(over.captures[0].samples[s].bias, 3.0, 1e-9);
    EXPECT_NEAR(over.captures[0].samples[s].rmse, 3.0, 1e-9);
    EXPECT_NEAR(under.captures[0].samples[s].bias, -2.5, 1e-9);
    EXPECT_NEAR(under.captures[0].samples[s].rmse, 2.5, 1e-9);
    for (double e : under.captures[0].errors_of(s)) EXPECT_NEAR(e, -2.5, 1e-9);
  }
}

TEST(SampleErrors, OnlyTheErringDirectionShowsAnError) {
  // Wrong only at the zenith: the per-sample RMSE points at the zenith sample (index 0 of the
  // synthetic layout), every other sample is exact.
  const std::vector<MeasuredCapture> captures = {testing::synthetic_capture(sky)};
  const FunctionModel model([](const ViewDirection& v, double nm) {
    return sky(v, nm) + (v.zenith_rad < 0.01 ? 0.009 : 0.0);
  });
  const EvaluationResult r = evaluate_sky_model(model, captures);
  const CaptureEvaluation& c = r.captures[0];
  for (const SampleEvaluation& s : c.samples) {
    if (s.view_zenith_deg < 0.5) {
      EXPECT_EQ(s.index, 0);
      EXPECT_NEAR(s.rmse, 9.0, 1e-9);
      EXPECT_NEAR(s.bias, 9.0, 1e-9);
    } else {
      EXPECT_NEAR(s.rmse, 0.0, 1e-12) << s.index;
    }
  }
  EXPECT_NEAR(c.rmse, 9.0 / std::sqrt(81.0), 1e-9);
}

}  // namespace
}  // namespace clearsky
