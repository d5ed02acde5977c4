// Evaluations of broadband irradiance datasets (api/evaluation/broadband_evaluation.h,
// broadband_evaluation_runner.h) on a real database: a series that Nishita 1993 made itself
// (broadband GHI and DNI at its default atmosphere) is evaluated with an RMSE of 0 and stored
// with its per-sample errors; a different beta is seen; a night sample is not compared; a model
// without a broadband answer is refused naming `model`.
#include <gtest/gtest.h>

#include <cmath>

#include "api/error/api_error.h"
#include "api/evaluation/broadband_evaluation_runner.h"
#include "models/registry.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/irradiance_run_results.h"
#include "storage/schema/migrations.h"
#include "tests/support/temp_dir.h"

namespace clearsky::api {
namespace {

// 2013-05-27 at Rhodes Hall: 09:30 and 12:00 EDT, and 02:00 EDT (night).
std::vector<storage::IrradianceSample> rhodes_instants() {
  std::vector<storage::IrradianceSample> samples;
  for (double t : {1369661400.0, 1369670400.0, 1369634400.0}) {
    storage::IrradianceSample s;
    s.time_utc_s = t;
    s.utc_offset_minutes = -240;
    s.latitude_deg = 42.443449;
    s.longitude_deg = -76.481962;
    s.elevation_m = 250;
    samples.push_back(s);
  }
  return samples;
}

const ModelFactory& factory_of(const std::string& id) {
  const ModelFactory* factory = find_model(id);
  EXPECT_NE(factory, nullptr) << id;
  return *factory;
}

TEST(BroadbandEvaluation, AModelsOwnSeriesHasNoErrorAndANightSampleIsNotCompared) {
  clearsky::testing::TempDir dir;
  storage::Database db = storage::open_database(dir.path / "sky.db");
  std::vector<storage::IrradianceSample> samples = rhodes_instants();
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
  std::vector<storage::IrradianceSample> samples = rhodes_instants();
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
    EXPECT_EQ(e.parameter(), "model");
  }
}

}  // namespace
}  // namespace clearsky::api
