// Tests of the paper's RMSE (models/evaluation/evaluate_model.h) with test-only models whose
// error against synthetic captures is known by hand.
#include "models/evaluation/evaluate_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "models/core/fit_domain.h"
#include "tests/models/evaluation/function_model.h"
#include "tests/models/evaluation/synthetic_sky.h"

namespace clearsky {
namespace {

using testing::FunctionModel;
using testing::test_descriptor;

// Returns the measured spectra of a capture, read at the grid wavelengths.
class MeasuredSkyModel : public SkyModel {
 public:
  explicit MeasuredSkyModel(const MeasuredCapture& capture)
      : SkyModel(ModelConfig{}), capture_(capture) {}
  const ModelDescriptor& descriptor() const override { return test_descriptor(); }

 protected:
  void compute_sky_radiance(const SunState&, const Viewpoint&, std::span<const ViewDirection> views,
                            SpectralBatch& out) const override {
    for (std::size_t v = 0; v < views.size(); ++v) {
      for (const MeasuredSample& s : capture_.samples) {
        if (cos_angle_between(s.view, views[v]) < std::cos(1e-6)) continue;
        auto spectrum = out.spectrum(v);
        for (std::size_t i = 0; i < wavelengths().size(); ++i)
          spectrum[i] = s.radiance.at(wavelengths()[i], OutOfRange::hold_end_values);
      }
    }
  }
  Spectrum compute_sun_irradiance(const SunState&, const Viewpoint&) const override {
    return Spectrum(wavelengths().size(), 0.0);
  }

 private:
  const MeasuredCapture& capture_;
};

// A smooth, sun-dependent sky in W/(m2.sr.nm).
double sky(const ViewDirection& view, double nm) {
  return 0.05 + 0.02 * std::cos(view.zenith_rad) + 0.01 * std::sin(view.azimuth_rad) +
         1e-5 * (nm - 500);
}

TEST(EvaluateModel, ModelReturningTheMeasurementsHasZeroError) {
  const std::vector<MeasuredCapture> captures = {testing::synthetic_capture(sky)};
  const MeasuredSkyModel model(captures[0]);
  const EvaluationResult r = evaluate_sky_model(model, captures);
  EXPECT_EQ(r.rmse, 0.0);
  ASSERT_EQ(r.captures.size(), 1u);
  EXPECT_EQ(r.captures[0].values_compared, 81u * 31u);
  EXPECT_EQ(r.model_id, "test-model");
}

TEST(EvaluateModel, ComparesThe31GridWavelengthsFrom360To712Point5) {
  const std::vector<MeasuredCapture> captures = {testing::synthetic_capture(sky)};
  // Wrong only beyond 720 nm: invisible to the paper's measure.
  const FunctionModel model(
      [](const ViewDirection& v, double nm) { return sky(v, nm) + (nm > 720 ? 1.0 : 0.0); });
  const EvaluationResult r = evaluate_sky_model(model, captures);
  ASSERT_EQ(r.wavelengths_nm.size(), 31u);
  EXPECT_DOUBLE_EQ(r.wavelengths_nm.front(), 360.0);
  EXPECT_DOUBLE_EQ(r.wavelengths_nm.back(), 712.5);
  EXPECT_NEAR(r.rmse, 0.0, 1e-9);
}

TEST(EvaluateModel, ConstantOffsetGivesTheOffsetInMilliwatts) {
  const std::vector<MeasuredCapture> captures = {testing::synthetic_capture(sky),
                                                 testing::synthetic_capture(sky)};
  const FunctionModel model([](const ViewDirection& v, double nm) { return sky(v, nm) - 0.0025; });
  const EvaluationResult r = evaluate_sky_model(model, captures);
  EXPECT_NEAR(r.rmse, 2.5, 1e-9);
  for (const auto& c : r.captures) EXPECT_NEAR(c.rmse, 2.5, 1e-9);
}

TEST(EvaluateModel, TotalIsTheRootMeanOfSquaredCaptureErrors) {
  // Uniform skies of 3 and 4 mW against a black model: capture RMSE 3 and 4, total
  // sqrt((9 + 16) / 2).
  const std::vector<MeasuredCapture> captures = {
      testing::synthetic_capture([](const ViewDirection&, double) { return 0.003; }),
      testing::synthetic_capture([](const ViewDirection&, double) { return 0.004; })};
  const FunctionModel model([](const ViewDirection&, double) { return 0.0; });
  const EvaluationResult r = evaluate_sky_model(model, captures);
  ASSERT_EQ(r.captures.size(), 2u);
  EXPECT_NEAR(r.captures[0].rmse, 3.0, 1e-12);
  EXPECT_NEAR(r.captures[1].rmse, 4.0, 1e-12);
  EXPECT_NEAR(r.rmse, std::sqrt(12.5), 1e-12);
}

TEST(EvaluateModel, HandComputedErrorOfAWavelengthDependentModel) {
  // Model error e(nm) = 1e-5 * (nm - 360) W: RMSE = 1e-2 * sqrt(mean over the 31 grid
  // wavelengths of (11.75 i)^2) mW = 0.1175 * sqrt(sum i^2 / 31), sum_{i<31} i^2 = 9455.
  const std::vector<MeasuredCapture> captures = {testing::synthetic_capture(sky)};
  const FunctionModel model(
      [](const ViewDirection& v, double nm) { return sky(v, nm) + 1e-5 * (nm - 360); });
  const EvaluationResult r = evaluate_sky_model(model, captures);
  EXPECT_NEAR(r.rmse, 0.1175 * std::sqrt(9455.0 / 31.0), 1e-9);
}

TEST(EvaluateModel, UsesTheEstimatedSunAzimuthAndTheComputedZenith) {
  MeasuredCapture capture = testing::synthetic_capture(sky, 35.0, 140.0);
  capture.sun_azimuth_estimated_deg = 131.2;
  const std::vector<MeasuredCapture> captures = {capture};
  const FunctionModel model(sky);
  const EvaluationResult estimated = evaluate_sky_model(model, captures);
  EXPECT_DOUBLE_EQ(estimated.captures[0].sun_zenith_deg, 35.0);
  EXPECT_DOUBLE_EQ(estimated.captures[0].sun_azimuth_deg, 131.2);
  EvaluationOptions computed;
  computed.use_estimated_sun_azimuth = false;
  EXPECT_DOUBLE_EQ(evaluate_sky_model(model, captures, computed).captures[0].sun_azimuth_deg,
                   140.0);
  EXPECT_EQ(estimated.captures[0].time_iso, "2013-05-27T09:30:00-04:00");
}

// A capture without an estimated sun azimuth (one of another layout than Kider's, the open
// format's) is given the computed one.
TEST(EvaluateModel, WithoutAnEstimateTheComputedSunAzimuthIsUsed) {
  MeasuredCapture capture = testing::synthetic_capture(sky, 35.0, 140.0);
  capture.sun_azimuth_estimated_deg = kNotComputed;
  const FunctionModel model(sky);
  const EvaluationResult r = evaluate_sky_model(model, std::vector<MeasuredCapture>{capture});
  EXPECT_DOUBLE_EQ(r.captures[0].sun_azimuth_deg, 140.0);
  EXPECT_TRUE(r.captures[0].answered());
}

// Spectra of any range: the compared wavelengths are at most those the measurements reach, and
// a sample that does not reach them all is excluded as wavelength_out_of_range, and counted.
TEST(EvaluateModel, SpectraThatDoNotReachTheComparedWavelengthsAreExcluded) {
  MeasuredCapture capture = testing::synthetic_capture(sky);
  const auto cut = [](const TabulatedSpectrum& s, double from_nm, double to_nm) {
    std::vector<double> nm, values;
    for (std::size_t i = 0; i < s.wavelengths_nm().size(); ++i) {
      if (s.wavelengths_nm()[i] < from_nm || s.wavelengths_nm()[i] > to_nm) continue;
      nm.push_back(s.wavelengths_nm()[i]);
      values.push_back(s.values()[i]);
    }
    return TabulatedSpectrum(std::move(nm), std::move(values));
  };
  // Every spectrum over 400..700 nm, sample 7's over 500..600 nm only.
  for (MeasuredSample& sample : capture.samples) sample.radiance = cut(sample.radiance, 400, 700);
  capture.samples[7].radiance = cut(capture.samples[7].radiance, 500, 600);
  const FunctionModel model(sky);
  const EvaluationResult r = evaluate_sky_model(model, std::vector<MeasuredCapture>{capture});
  // The grid wavelengths 360 + 11.75 i within 400..700 nm: i = 4 (407) to 28 (689).
  ASSERT_EQ(r.wavelengths_nm.size(), 25u);
  EXPECT_DOUBLE_EQ(r.wavelengths_nm.front(), 407.0);
  EXPECT_DOUBLE_EQ(r.wavelengths_nm.back(), 689.0);
  EXPECT_NEAR(r.rmse, 0.0, 1e-9);
  EXPECT_EQ(r.samples_compared, 80u);
  EXPECT_EQ(r.samples_excluded, 1u);
  ASSERT_EQ(r.captures[0].excluded.size(), 1u);
  EXPECT_EQ(r.captures[0].excluded[0],
            (OutOfDomainSamples{SampleStatus::wavelength_out_of_range, {7}}));
  // No measured wavelength in the compared range: every sample excluded, the capture unanswered.
  for (MeasuredSample& sample : capture.samples) sample.radiance = cut(sample.radiance, 502, 503);
  const EvaluationResult none = evaluate_sky_model(model, std::vector<MeasuredCapture>{capture});
  EXPECT_EQ(none.captures_unanswered, 1u);
  EXPECT_EQ(none.samples_excluded, 81u);
}

TEST(EvaluateModel, RefusesUnpreparedCaptures) {
  const FunctionModel model(sky);
  MeasuredCapture no_sun = testing::synthetic_capture(sky);
  no_sun.sun_azimuth_estimated_deg = kNotComputed;
  no_sun.sun_azimuth_computed_deg = kNotComputed;
  EXPECT_THROW(evaluate_sky_model(model, std::vector<MeasuredCapture>{no_sun}),
               std::invalid_argument);
  MeasuredCapture defective = testing::synthetic_capture(sky);
  defective.samples[5].quality_flags |= kSampleKnownDefective;
  EXPECT_THROW(evaluate_sky_model(model, std::vector<MeasuredCapture>{defective}),
               std::invalid_argument);
  EXPECT_THROW(evaluate_sky_model(model, std::vector<MeasuredCapture>{}), std::invalid_argument);
}

// A capture whose sun the model cannot answer is unanswered, counted, and left out of the
// total; the other captures are evaluated as alone.
TEST(EvaluateModel, CaptureWhoseSunTheModelCannotAnswerIsUnanswered) {
  const FunctionModel model([](const ViewDirection& v, double nm) { return sky(v, nm) - 0.002; });
  const std::vector<MeasuredCapture> captures = {testing::synthetic_capture(sky, 95.0, 120.0),
                                                 testing::synthetic_capture(sky)};
  const EvaluationResult r = evaluate_sky_model(model, captures);
  ASSERT_EQ(r.captures.size(), 2u);
  EXPECT_FALSE(r.captures[0].answered());
  EXPECT_EQ(r.captures[0].values_compared, 0u);
  ASSERT_EQ(r.captures[0].excluded.size(), 1u);
  EXPECT_EQ(r.captures[0].excluded[0].reason, SampleStatus::sun_below_horizon_unsupported);
  EXPECT_EQ(r.captures[0].excluded[0].indices.size(), 81u);
  EXPECT_TRUE(r.captures[1].answered());
  EXPECT_NEAR(r.rmse, 2.0, 1e-9);  // the answered capture only
  EXPECT_EQ(r.samples_compared, 81u);
  EXPECT_EQ(r.samples_excluded, 81u);
  EXPECT_EQ(r.captures_unanswered, 1u);
  // Clamped: the sun at the model's largest zenith (90), every sample listed as clamped.
  EvaluationOptions clamp;
  clamp.out_of_domain = OutOfDomain::clamp;
  const EvaluationResult c = evaluate_sky_model(model, captures, clamp);
  EXPECT_TRUE(c.captures[0].answered());
  EXPECT_DOUBLE_EQ(c.captures[0].sun_zenith_deg, 90.0);
  ASSERT_EQ(c.captures[0].clamped.size(), 1u);
  EXPECT_EQ(c.captures[0].clamped[0].reason, SampleStatus::sun_below_horizon_unsupported);
  EXPECT_EQ(c.samples_compared, 162u);
  EXPECT_EQ(c.samples_clamped, 81u);
  EXPECT_NEAR(c.rmse, 2.0, 1e-9);
}

// A model that answers no sample of any capture: every capture unanswered, no RMSE, no throw.
TEST(EvaluateModel, NoAnsweredCaptureGivesNoRmse) {
  const FunctionModel model(sky);
  const std::vector<MeasuredCapture> captures = {testing::synthetic_capture(sky, 95.0, 120.0)};
  const EvaluationResult r = evaluate_sky_model(model, captures);
  EXPECT_TRUE(std::isnan(r.rmse));
  EXPECT_EQ(r.samples_compared, 0u);
  EXPECT_EQ(r.captures_unanswered, 1u);
}

// Samples outside a fitted model's domain: excluded (and the capture's RMSE over the others,
// exactly as if those samples were not measured), or clamped to the fit's limit of no light by
// the model's own clamp_negative_fit.
TEST(EvaluateModel, SamplesOutsideTheFitDomainAreExcludedOrClamped) {
  static const ModelDescriptor fit_descriptor = [] {
    ModelDescriptor d = test_descriptor();
    d.id = "fit";
    d.parameters = {{.name = kClampNegativeFitOption,
                     .description = "0 for negative",
                     .default_value = 0,
                     .min_value = 0,
                     .max_value = 1,
                     .integer = true}};
    return d;
  }();
  // Negative (outside the fit) below 20 degrees of elevation, the measured sky elsewhere.
  class FitModel : public SkyModel {
   public:
    explicit FitModel(ModelConfig config) : SkyModel(std::move(config)) {}
    const ModelDescriptor& descriptor() const override { return fit_descriptor; }

   protected:
    void compute_sky_radiance(const SunState&, const Viewpoint&,
                              std::span<const ViewDirection> views,
                              SpectralBatch& out) const override {
      const bool clamp = option_or_default(fit_descriptor, config(), kClampNegativeFitOption) != 0;
      for (std::size_t v = 0; v < views.size(); ++v) {
        auto spectrum = out.spectrum(v);
        for (std::size_t i = 0; i < wavelengths().size(); ++i)
          spectrum[i] =
              views[v].zenith_rad > 70 * kDegree ? -0.01 : sky(views[v], wavelengths()[i]);
        out.status[v] = apply_fit_domain(spectrum, clamp);
      }
    }
    Spectrum compute_sun_irradiance(const SunState&, const Viewpoint&) const override {
      return Spectrum(wavelengths().size(), 0.0);
    }
  };
  const ModelFactory factory{&fit_descriptor,
                             [](const ModelConfig& config, const PrecomputeContext&) {
                               return std::shared_ptr<const SkyModel>(new FitModel(config));
                             }};
  const std::vector<MeasuredCapture> captures = {testing::synthetic_capture(sky)};
  const EvaluationResult excluded = evaluate_model(factory, ModelConfig{}, captures);
  const CaptureEvaluation& e = excluded.captures[0];
  ASSERT_EQ(e.excluded.size(), 1u);
  EXPECT_EQ(e.excluded[0].reason, SampleStatus::outside_fit_domain);
  const std::size_t low = e.excluded[0].indices.size();  // the lowest ring
  EXPECT_EQ(low + e.samples.size(), 81u);
  EXPECT_GT(low, 0u);
  EXPECT_NEAR(excluded.rmse, 0.0, 1e-9);  // the answered samples are the measured sky
  EXPECT_EQ(e.values_compared, e.samples.size() * 31u);

  EvaluationOptions clamp;
  clamp.out_of_domain = OutOfDomain::clamp;
  const EvaluationResult clamped = evaluate_model(factory, ModelConfig{}, captures, clamp);
  const CaptureEvaluation& c = clamped.captures[0];
  EXPECT_TRUE(c.excluded.empty());
  ASSERT_EQ(c.clamped.size(), 1u);
  EXPECT_EQ(c.clamped[0].indices, e.excluded[0].indices);
  EXPECT_EQ(c.samples.size(), 81u);
  // The clamped samples answer 0: their error is minus the measurement.
  for (const SampleEvaluation& s : c.samples) {
    const bool was_clamped = std::find(c.clamped[0].indices.begin(), c.clamped[0].indices.end(),
                                       s.index) != c.clamped[0].indices.end();
    EXPECT_EQ(was_clamped, s.bias < -1.0) << s.index;
  }
}

std::shared_ptr<const SkyModel> create_offset_model(const ModelConfig& config,
                                                    const PrecomputeContext&) {
  return std::make_shared<FunctionModel>(
      [](const ViewDirection& v, double nm) { return sky(v, nm) + 0.001; }, config);
}

TEST(EvaluateModel, FactoryPathTimesThePrecomputation) {
  const ModelFactory factory{&test_descriptor(), &create_offset_model};
  const std::vector<MeasuredCapture> captures = {testing::synthetic_capture(sky)};
  const EvaluationResult r = evaluate_model(factory, ModelConfig{}, captures, {});
  EXPECT_NEAR(r.rmse, 1.0, 1e-9);
  EXPECT_GE(r.precompute_seconds, 0.0);
  EXPECT_GE(r.evaluate_seconds, 0.0);
  EXPECT_EQ(r.model_version, "1");
}

}  // namespace
}  // namespace clearsky
