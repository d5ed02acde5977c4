// Evaluations of broadband irradiance datasets (api/evaluation/broadband_evaluation.h,
// broadband_evaluation_runner.h) on a real database: a series that Nishita 1993 made itself
// (broadband GHI and DNI at its default atmosphere) is evaluated with an RMSE of 0 and stored
// with its per-sample errors; a different beta is seen; a night sample is not compared; a model
// without a broadband answer is refused naming `models`; a sample averaging an hour is compared
// with the model's mean over that hour; the model answers at the site's elevation.
#include <gtest/gtest.h>

#include <cmath>

#include "api/error/api_error.h"
#include "api/evaluation/broadband_evaluation_runner.h"
#include "models/registry.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/irradiance_run_results.h"
#include "storage/schema/migrations.h"
#include "tests/support/rhodes_irradiance_instants.h"
#include "tests/support/temp_dir.h"

namespace clearsky::api {
namespace {

using clearsky::testing::rhodes_irradiance_instants;

const ModelFactory& factory_of(const std::string& id) {
  const ModelFactory* factory = find_model(id);
  EXPECT_NE(factory, nullptr) << id;
  return *factory;
}

TEST(BroadbandEvaluation, AModelsOwnSeriesHasNoErrorAndANightSampleIsNotCompared) {
  clearsky::testing::TempDir dir;
  storage::Database db = storage::open_database(dir.path / "sky.db");
  std::vector<storage::IrradianceSample> samples = rhodes_irradiance_instants();
  const auto model = factory_of("nishita93").create(ModelConfig{}, {});
  const auto modelled = modelled_broadband_irradiance(*model, samples);
  ASSERT_TRUE(modelled[0].ghi_w_m2);
  EXPECT_GT(*modelled[1].ghi_w_m2, *modelled[0].ghi_w_m2);  // noon above morning
  EXPECT_GT(*modelled[1].ghi_w_m2, 500);
  EXPECT_FALSE(modelled[2].ghi_w_m2);  // night
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i].ghi_w_m2 = modelled[i].ghi_w_m2.value_or(0.0);
    if (i == 0) samples[i].dni_w_m2 = modelled[i].dni_w_m2;
  }
  const std::int64_t dataset = storage::DatasetRepository(db).find_or_create(
      "roof", "irradiance", storage::kBroadbandIrradianceKind);
  storage::IrradianceSampleRepository(db).insert(dataset, samples);
  ASSERT_TRUE(is_broadband_dataset(db, "roof"));

  EvaluationRequest request;
  request.dataset = "roof";
  request.models = {"nishita93"};
  const BroadbandEvaluationReport report =
      run_broadband_evaluation(db, request, registered_models());
  ASSERT_EQ(report.models.size(), 1u);
  const BroadbandModelRun& run = report.models[0];
  EXPECT_EQ(run.samples, 3);
  EXPECT_EQ(run.samples_sun_up, 2);
  ASSERT_EQ(run.components.size(), 2u);  // ghi and dni: no dhi measured
  EXPECT_EQ(run.components[0].component, "ghi");
  EXPECT_EQ(run.components[0].samples_compared, 2);
  EXPECT_NEAR(*run.components[0].rmse_w_m2, 0.0, 1e-9);
  EXPECT_EQ(run.components[1].component, "dni");
  EXPECT_EQ(run.components[1].samples_compared, 1);
  // Errors are in the dataset's order, by instant: the night sample (02:00) first.
  EXPECT_TRUE(std::isnan(run.components[0].errors_w_m2[0]));
  EXPECT_FALSE(std::isnan(run.components[0].errors_w_m2[1]));
  const auto stored = storage::IrradianceRunResultRepository(db).load(run.run_id);
  ASSERT_EQ(stored.size(), 2u);
  EXPECT_EQ(stored[0].errors_w_m2.size(), 3u);
  EXPECT_EQ(stored[0].samples_compared, 2);

  // Another beta: a different GHI, so a non-zero RMSE and a bias of one sign (more aerosol,
  // less direct light on the ground).
  request.parameters = {{"beta", 0.2}};
  const BroadbandModelRun hazy =
      run_broadband_evaluation(db, request, registered_models()).models[0];
  EXPECT_GT(*hazy.components[0].rmse_w_m2, 5.0);
  EXPECT_LT(*hazy.components[0].mean_bias_w_m2, 0.0);
}

TEST(BroadbandEvaluation, AModelWithoutABroadbandAnswerIsRefusedNamingModel) {
  clearsky::testing::TempDir dir;
  storage::Database db = storage::open_database(dir.path / "sky.db");
  std::vector<storage::IrradianceSample> samples = rhodes_irradiance_instants();
  samples[0].ghi_w_m2 = 650;
  storage::IrradianceSampleRepository(db).insert(
      storage::DatasetRepository(db).find_or_create("roof", "irradiance",
                                                    storage::kBroadbandIrradianceKind),
      {samples[0]});
  EvaluationRequest request;
  request.dataset = "roof";
  request.models = {"preetham"};
  try {
    run_broadband_evaluation(db, request, registered_models());
    FAIL() << "preetham was not refused";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 422);
    EXPECT_EQ(e.code(), "broadband_unavailable");
    EXPECT_EQ(e.parameter(), "models");
  }
}

// A sample averaging the hour before 10:30 EDT: the measured value is the model's own mean over
// that hour, made here independently by the trapezoid rule on 121 instants (30 s apart), so the
// evaluation's 3 Gauss-Legendre nodes must find it to a small fraction of a W/m2; compared as
// an instantaneous sample at the label, the morning's rise (about 90 W/m2 of GHI that hour)
// shows as a bias of tens of W/m2.
TEST(BroadbandEvaluation, AnAveragedSampleIsComparedWithTheModelsMeanOverItsPeriod) {
  clearsky::testing::TempDir dir;
  storage::Database db = storage::open_database(dir.path / "sky.db");
  const auto model = factory_of("nishita93").create(ModelConfig{}, {});
  const double label = 1369665000.0;  // 2013-05-27T10:30:00-04:00
  const double period_s = 3600.0;
  storage::IrradianceSample site = rhodes_irradiance_instants()[0];
  std::vector<storage::IrradianceSample> instants;
  for (int i = 0; i <= 120; ++i) {
    storage::IrradianceSample s = site;
    s.time_utc_s = label - period_s + 30.0 * i;
    instants.push_back(s);
  }
  const auto dense = modelled_broadband_irradiance(*model, instants);
  double ghi_mean = 0, dni_mean = 0;
  for (int i = 0; i <= 120; ++i) {
    const double w = (i == 0 || i == 120) ? 0.5 / 120 : 1.0 / 120;
    ghi_mean += w * *dense[i].ghi_w_m2;
    dni_mean += w * *dense[i].dni_w_m2;
  }
  storage::IrradianceSample averaged = site;
  averaged.time_utc_s = label;
  averaged.averaging_s = period_s;
  averaged.ghi_w_m2 = ghi_mean;
  averaged.dni_w_m2 = dni_mean;
  const auto modelled = modelled_broadband_irradiance(*model, {averaged});
  // The trapezoid's own error on 30 s steps is below 0.01 W/m2 (h^2/12 of the curvature).
  EXPECT_NEAR(*modelled[0].ghi_w_m2, ghi_mean, 0.05);
  EXPECT_NEAR(*modelled[0].dni_w_m2, dni_mean, 0.05);
  EXPECT_GT(*dense.back().ghi_w_m2 - *dense.front().ghi_w_m2, 50.0);

  const std::int64_t dataset = storage::DatasetRepository(db).find_or_create(
      "hourly", "irradiance", storage::kBroadbandIrradianceKind);
  storage::IrradianceSample instantaneous = averaged;
  instantaneous.averaging_s.reset();
  storage::IrradianceSampleRepository(db).insert(dataset, {averaged});
  EvaluationRequest request;
  request.dataset = "hourly";
  request.models = {"nishita93"};
  const BroadbandModelRun run =
      run_broadband_evaluation(db, request, registered_models()).models[0];
  EXPECT_LT(*run.components[0].rmse_w_m2, 0.05);
  EXPECT_EQ(run.components[0].samples_compared, 1);

  // The same value taken as instantaneous at the label: the model at 10:30 is above the hour's
  // mean, by about half the hour's rise.
  const auto at_label = modelled_broadband_irradiance(*model, {instantaneous});
  EXPECT_GT(*at_label[0].ghi_w_m2 - ghi_mean, 20.0);
}

// The site's elevation: Nishita 1993 at 3000 m has less air and aerosol above it than at sea
// level, so more direct sun.
TEST(BroadbandEvaluation, TheModelAnswersAtTheSitesElevation) {
  const auto model = factory_of("nishita93").create(ModelConfig{}, {});
  storage::IrradianceSample low = rhodes_irradiance_instants()[1];
  low.elevation_m = 0;
  storage::IrradianceSample high = low;
  high.elevation_m = 3000;
  const auto modelled = modelled_broadband_irradiance(*model, {low, high});
  EXPECT_GT(*modelled[1].dni_w_m2, *modelled[0].dni_w_m2 + 10.0);
}

}  // namespace
}  // namespace clearsky::api
