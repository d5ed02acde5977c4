// /v1/evaluations on a broadband irradiance dataset without a socket
// (api/evaluation/evaluations_api.h, evaluation_pool.h; docs/data-api.md "Evaluations of
// broadband irradiance"), on a real database file: the request is accepted ("all" too), a
// model without a broadband answer is refused naming `models`; a ticket runs on the pool and
// its run shows the per-component RMSE and bias in W/m2 (0 for a series Nishita 1993 made
// itself), in the list too, with each sample's error on request. The ticket is polled with a
// generous deadline (a loaded machine); nothing asserts a duration.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "api/error/api_error.h"
#include "api/evaluation/broadband_evaluation.h"
#include "api/evaluation/evaluation_pool.h"
#include "api/evaluation/evaluations_api.h"
#include "models/registry.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/irradiance_sample_repository.h"
#include "storage/schema/migrations.h"
#include "tests/support/rhodes_irradiance_instants.h"
#include "tests/support/temp_dir.h"

namespace clearsky::api {
namespace {

// 09:30, 12:00 and 02:00 EDT on 2013-05-27 at Rhodes Hall: GHI and DNI as Nishita 1993 gives
// them at its defaults (the night sample 0).
void store_nishita_series(storage::Database& db, const std::string& name) {
  std::vector<storage::IrradianceSample> samples = clearsky::testing::rhodes_irradiance_instants();
  const auto model = find_model("nishita93")->create(ModelConfig{}, {});
  const auto modelled = modelled_broadband_irradiance(*model, samples);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i].ghi_w_m2 = modelled[i].ghi_w_m2.value_or(0.0);
    samples[i].dni_w_m2 = modelled[i].dni_w_m2.value_or(0.0);
  }
  storage::IrradianceSampleRepository(db).insert(
      storage::DatasetRepository(db).find_or_create(name, "irradiance",
                                                    storage::kBroadbandIrradianceKind),
      samples);
}

TEST(BroadbandEvaluationsApi, RequestsAreAcceptedAndModelsWithoutABroadbandAnswerRefused) {
  clearsky::testing::TempDir dir;
  storage::Database db = storage::open_database(dir.path / "sky.db");
  store_nishita_series(db, "roof");
  const EvaluationRequest all = parse_evaluation_request(
      db, R"({"dataset": "roof", "models": "all"})", registered_models(), "test");
  EXPECT_EQ(all.dataset, "roof");
  EXPECT_NO_THROW(parse_evaluation_request(db, R"({"dataset": "roof", "models": ["bruneton"]})",
                                           registered_models(), "test"));
  for (const char* body : {R"({"dataset": "roof", "models": ["preetham"]})",
                           R"({"dataset": "roof", "models": ["nishita93", "hosek"]})"}) {
    try {
      parse_evaluation_request(db, body, registered_models(), "test");
      FAIL() << body << " was accepted";
    } catch (const ApiError& e) {
      EXPECT_EQ(e.status(), 422) << body;
      EXPECT_EQ(e.code(), "broadband_unavailable") << body;
      EXPECT_EQ(e.parameter(), "models") << body;
    }
  }
}

TEST(BroadbandEvaluationsApi, ATicketRunsOnThePoolAndItsRunShowsEachComponentInWattsPerM2) {
  clearsky::testing::TempDir dir;
  const auto file = dir.path / "sky.db";
  storage::Database db = storage::open_database(file);
  store_nishita_series(db, "roof");
  EvaluationPool pool([file] { return storage::open_database(file); }, registered_models());
  const std::int64_t ticket = pool.submit(parse_evaluation_request(
      db, R"({"dataset": "roof", "models": ["nishita93"]})", registered_models(), "test"));
  std::optional<TicketState> state;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(10);
  while (std::chrono::steady_clock::now() < deadline) {
    state = pool.ticket(ticket);
    if (state && state->status != "queued" && state->status != "running") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_TRUE(state);
  ASSERT_EQ(state->status, "succeeded") << state->error;
  ASSERT_EQ(state->models.size(), 1u);
  EXPECT_EQ(state->models[0].model, "nishita93");
  ASSERT_EQ(state->run_ids.size(), 1u);

  const nlohmann::ordered_json run = show_evaluation(db, state->run_ids[0]);
  EXPECT_EQ(run["status"], "succeeded");
  EXPECT_EQ(run["rmse_unit"], "W/m2");
  EXPECT_NEAR(run["rmse"].get<double>(), 0.0, 1e-9);
  EXPECT_EQ(run["samples_compared"], 4);  // 2 of GHI and 2 of DNI, pooled
  EXPECT_EQ(run["wavelength_range_nm"], nlohmann::ordered_json({300.0, 4000.0}));
  const auto& components = run["irradiance_components"];
  ASSERT_EQ(components.size(), 2u) << run.dump();  // ghi and dni measured
  EXPECT_EQ(components[0]["component"], "ghi");
  EXPECT_EQ(components[0]["samples_compared"], 2);
  EXPECT_NEAR(components[0]["rmse_w_m2"].get<double>(), 0.0, 1e-9);
  EXPECT_NEAR(components[0]["mean_bias_w_m2"].get<double>(), 0.0, 1e-9);
  EXPECT_EQ(components[1]["component"], "dni");
  EXPECT_FALSE(components[0].contains("errors_w_m2"));
  bool says_altitude = false;
  for (const auto& step : run["processing_steps"])
    says_altitude = says_altitude ||
                    step.get<std::string>() == "model at the site's elevation (altitude 250 m)";
  EXPECT_TRUE(says_altitude) << run["processing_steps"].dump();

  ShowEvaluationOptions with_samples;
  with_samples.samples = SampleDetail::summary;
  const auto errors = show_evaluation(db, state->run_ids[0],
                                      with_samples)["irradiance_components"][0]["errors_w_m2"];
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_TRUE(errors[0].is_null());  // the night sample, first by instant
  EXPECT_NEAR(errors[1].get<double>(), 0.0, 1e-9);

  const ListPage page = list_evaluations(db, parse_evaluation_filter(Parameters("GET /test")));
  ASSERT_EQ(page.items.size(), 1u);
  EXPECT_EQ(page.items[0]["rmse_unit"], "W/m2");
  EXPECT_EQ(page.items[0]["samples_compared"], 4);
  EXPECT_EQ(page.items[0]["irradiance_components"].size(), 2u);
  EXPECT_EQ(page.items[0]["irradiance_components"][1]["component"], "dni");
}

}  // namespace
}  // namespace clearsky::api
