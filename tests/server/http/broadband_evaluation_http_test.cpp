// Evaluations and jobs on a broadband irradiance dataset through the real `clearsky serve` and
// its database (docs/data-api.md "Evaluations of broadband irradiance"): a series Nishita 1993
// made itself at the site's elevation is POSTed for evaluation, the ticket followed to
// `succeeded`, and the run answers each component's RMSE and bias in W/m2 (0 here), in the list
// too; naming Preetham (no broadband answer) is a 422 naming `models`; a job on the dataset is
// created. Timeouts are generous (a loaded machine); nothing asserts a duration.
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <nlohmann/json.hpp>
#include <thread>

#include "api/evaluation/broadband_evaluation.h"
#include "models/registry.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/irradiance_sample_repository.h"
#include "tests/server/http/hostile_clients.h"
#include "tests/server/http/watched_serve_process.h"
#include "tests/support/rhodes_irradiance_instants.h"

namespace clearsky::server {
namespace {

using testing::WatchedServeProcess;

const httplib::Headers kToken = {{"Authorization", "Bearer t0ken"}};

nlohmann::json json_of(const httplib::Result& r) {
  return nlohmann::json::parse(r->body, nullptr, false);
}

// 09:30, 12:00 and 02:00 EDT on 2013-05-27 at Rhodes Hall (250 m): GHI, DHI and DNI as Nishita
// 1993 gives them at its defaults.
void store_nishita_series(const std::filesystem::path& file) {
  storage::Database db = storage::Database::open(file);
  std::vector<storage::IrradianceSample> samples = clearsky::testing::rhodes_irradiance_instants();
  const auto model = find_model("nishita93")->create(ModelConfig{}, {});
  const auto modelled = api::modelled_broadband_irradiance(*model, samples);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i].ghi_w_m2 = modelled[i].ghi_w_m2.value_or(0.0);
    samples[i].dhi_w_m2 = modelled[i].dhi_w_m2.value_or(0.0);
    samples[i].dni_w_m2 = modelled[i].dni_w_m2.value_or(0.0);
  }
  storage::IrradianceSampleRepository(db).insert(
      storage::DatasetRepository(db).find_or_create("roof", "irradiance",
                                                    storage::kBroadbandIrradianceKind),
      samples);
}

TEST(BroadbandEvaluationOverHttp, ATicketEvaluatesTheSeriesAndTheRunShowsEachComponent) {
  WatchedServeProcess server(
      {"--models", "nishita93,preetham", "--prebuild-three", "false", "--token", "t0ken"});
  ASSERT_GT(server.port(), 0) << server.log();
  ASSERT_TRUE(testing::ready(server.port(), std::chrono::seconds(300))) << server.log();
  store_nishita_series(server.directory() / "db.sqlite");
  auto c = server.client(120);

  const auto refused = c.Post("/v1/evaluations", kToken,
                              R"({"dataset": "roof", "models": ["preetham"]})", "application/json");
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 422) << refused->body;
  EXPECT_EQ(json_of(refused)["error"]["code"], "broadband_unavailable");
  EXPECT_EQ(json_of(refused)["error"]["parameter"], "models");

  const auto accepted = c.Post("/v1/evaluations", kToken, R"({"dataset": "roof", "models": "all"})",
                               "application/json");
  ASSERT_TRUE(accepted);
  ASSERT_EQ(accepted->status, 202) << accepted->body;
  // "all" on a broadband series: the models with a broadband answer (not preetham).
  EXPECT_EQ(json_of(accepted)["models"].size(), 1u) << accepted->body;
  EXPECT_EQ(json_of(accepted)["models"][0]["model"], "nishita93");
  const std::string location = accepted->get_header_value("Location");
  nlohmann::json ticket;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(10);
  while (std::chrono::steady_clock::now() < deadline) {
    const auto r = c.Get(location);
    ASSERT_TRUE(r);
    ticket = json_of(r);
    if (ticket["status"] != "queued" && ticket["status"] != "running") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_EQ(ticket["status"], "succeeded") << ticket.dump();
  const std::string run_id = std::to_string(ticket["runs"][0].get<std::int64_t>());

  const auto shown = c.Get("/v1/evaluations/" + run_id + "?samples=true");
  ASSERT_TRUE(shown);
  ASSERT_EQ(shown->status, 200) << shown->body;
  const nlohmann::json run = json_of(shown);
  EXPECT_EQ(run["rmse_unit"], "W/m2");
  EXPECT_NEAR(run["rmse"].get<double>(), 0.0, 1e-9);
  ASSERT_EQ(run["irradiance_components"].size(), 3u) << shown->body;
  const char* names[] = {"ghi", "dhi", "dni"};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& component = run["irradiance_components"][i];
    EXPECT_EQ(component["component"], names[i]);
    EXPECT_EQ(component["samples_compared"], 2);
    EXPECT_NEAR(component["rmse_w_m2"].get<double>(), 0.0, 1e-9);
    EXPECT_NEAR(component["mean_bias_w_m2"].get<double>(), 0.0, 1e-9);
    ASSERT_EQ(component["errors_w_m2"].size(), 3u);
    EXPECT_TRUE(component["errors_w_m2"][0].is_null());  // the night sample
  }

  const auto listed = c.Get("/v1/evaluations?dataset=roof");
  ASSERT_TRUE(listed);
  ASSERT_EQ(listed->status, 200) << listed->body;
  EXPECT_EQ(json_of(listed)[0]["irradiance_components"].size(), 3u) << listed->body;

  const auto job = c.Post("/v1/jobs", kToken,
                          R"({"name": "roof-hourly", "schedule": "0 * * * *", "dataset": "roof",
                              "models": ["nishita93"]})",
                          "application/json");
  ASSERT_TRUE(job);
  EXPECT_EQ(job->status, 201) << job->body;
  const auto refused_job = c.Post("/v1/jobs", kToken,
                                  R"({"name": "roof-preetham", "schedule": "0 * * * *",
                                      "dataset": "roof", "models": ["preetham"]})",
                                  "application/json");
  ASSERT_TRUE(refused_job);
  EXPECT_EQ(refused_job->status, 422) << refused_job->body;
}

}  // namespace
}  // namespace clearsky::server
