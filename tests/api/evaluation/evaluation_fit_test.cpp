// The fit parameter of evaluations and jobs (api/evaluation/evaluation_fit.h, docs/fits.md "In
// evaluations and jobs") on a real SQLite database with a dataset Preetham made at turbidity
// 3.4: a fit by id applies to its own model only, latest to each model its newest fit, a
// parameter given too is refused naming it, the checks before queueing refuse what the run
// could not do, and a run with a fit records the fit's id and values as its parameters and
// answers the RMSE of the same values given explicitly; latest is expanded when the run starts.
#include "api/evaluation/evaluation_fit.h"

#include <gtest/gtest.h>

#include "api/evaluation/evaluation_runner.h"
#include "api/evaluation/evaluations_api.h"
#include "models/registry.h"
#include "storage/repositories/evaluation_run_repository.h"
#include "storage/schema/migrations.h"
#include "tests/support/model_made_dataset.h"
#include "tests/support/stored_fit.h"
#include "tests/support/temp_dir.h"

namespace clearsky::api {
namespace {

using clearsky::testing::store_fit;

const ModelFactory& factory(const char* id) { return *find_model(id); }

class EvaluationFit : public ::testing::Test {
 protected:
  void SetUp() override {
    ModelConfig truth;
    truth.atmosphere.turbidity = 3.4;
    dataset = clearsky::testing::store_model_made_dataset(db, "made", "preetham", truth,
                                                          {{30.0, 120.0}, {45.0, 100.0}});
  }
  // The status, code and parameter of what f throws (0 when nothing).
  static std::tuple<int, std::string, std::string> refusal(const std::function<void()>& f) {
    try {
      f();
    } catch (const ApiError& e) {
      return {e.status(), e.code(), e.parameter()};
    }
    return {0, "", ""};
  }
  // Runs the evaluation of preetham with parameters; returns the run's stored parameters and
  // its RMSE.
  std::pair<nlohmann::json, double> run(const nlohmann::json& parameters) {
    EvaluationRequest request;
    request.dataset = "made";
    request.models = {"preetham"};
    request.parameters = parameters;
    const EvaluationReport report = run_evaluation(db, request);
    const auto stored = storage::EvaluationRunRepository(db).get(report.models.at(0).run_id);
    return {nlohmann::json::parse(stored->parameters), report.models.at(0).result.rmse};
  }
  clearsky::testing::TempDir dir;
  storage::Database db = storage::open_database(dir.path / "sky.db");
  std::int64_t dataset = 0;
};

TEST_F(EvaluationFit, AFitByIdAppliesToItsOwnModelOnly) {
  const std::int64_t id = store_fit(db, dataset, "preetham", {{"turbidity", 3.25}});
  const nlohmann::json given = {{"fit", id}, {"out_of_domain", "clamp"}};
  EXPECT_EQ(expand_evaluation_fit(db, given, *factory("preetham").descriptor),
            nlohmann::json({{"fit", id}, {"turbidity", 3.25}, {"out_of_domain", "clamp"}}));
  EXPECT_EQ(expand_evaluation_fit(db, given, *factory("hosek").descriptor),
            nlohmann::json({{"out_of_domain", "clamp"}}));
  EXPECT_EQ(expand_evaluation_fit(db, {{"turbidity", 3}}, *factory("preetham").descriptor),
            nlohmann::json({{"turbidity", 3}}));
  EXPECT_EQ(
      refusal([&] {
        expand_evaluation_fit(db, {{"fit", id}, {"turbidity", 3}}, *factory("preetham").descriptor);
      }),
      std::make_tuple(400, std::string("conflicting_parameters"), std::string("turbidity")));
}

TEST_F(EvaluationFit, LatestAppliesToEachRequestedModelItsNewestFit) {
  store_fit(db, dataset, "preetham", {{"turbidity", 3.0}});
  const std::int64_t newest = store_fit(db, dataset, "preetham", {{"turbidity", 3.5}});
  const std::int64_t of_hosek = store_fit(db, dataset, "hosek", {{"turbidity", 4.5}});
  for (const nlohmann::json& latest : {nlohmann::json("latest"), nlohmann::json("latest:made")}) {
    const nlohmann::json given = {{"fit", latest}};
    EXPECT_EQ(expand_evaluation_fit(db, given, *factory("preetham").descriptor),
              nlohmann::json({{"fit", newest}, {"turbidity", 3.5}}));
    EXPECT_EQ(expand_evaluation_fit(db, given, *factory("hosek").descriptor),
              nlohmann::json({{"fit", of_hosek}, {"turbidity", 4.5}}));
  }
}

TEST_F(EvaluationFit, TheChecksBeforeQueueingRefuseWhatTheRunCouldNotDo) {
  const std::int64_t id = store_fit(db, dataset, "preetham", {{"turbidity", 3.25}});
  const std::int64_t too_low = store_fit(db, dataset, "preetham", {{"turbidity", 1.5}});
  const std::int64_t running = store_fit(db, dataset, "preetham", {{"turbidity", 3.0}}, "running");
  const ModelFactory* preetham[] = {&factory("preetham")};
  const ModelFactory* hosek[] = {&factory("hosek")};
  const ModelFactory* both[] = {&factory("preetham"), &factory("hosek")};
  EXPECT_EQ(refusal([&] {
              check_evaluation_fit(db, {{"fit", id}}, both);
            }),
            std::make_tuple(0, std::string(), std::string()));
  EXPECT_EQ(refusal([&] {
              check_evaluation_fit(db, {{"fit", id}}, hosek);
            }),
            std::make_tuple(409, std::string("fit_model_mismatch"), std::string("fit")));
  EXPECT_EQ(refusal([&] {
              check_evaluation_fit(db, {{"fit", "latest"}}, hosek);
            }),
            std::make_tuple(404, std::string("unknown_fit"), std::string("fit")));
  EXPECT_EQ(refusal([&] {
              check_evaluation_fit(db, {{"fit", 999}}, preetham);
            }),
            std::make_tuple(404, std::string("unknown_fit"), std::string("fit")));
  EXPECT_EQ(refusal([&] {
              check_evaluation_fit(db, {{"fit", running}}, preetham);
            }),
            std::make_tuple(409, std::string("fit_not_succeeded"), std::string("fit")));
  // Preetham's turbidity starts at 2: a stored 1.5 is refused as the same value given.
  EXPECT_EQ(refusal([&] {
              check_evaluation_fit(db, {{"fit", too_low}}, preetham);
            }),
            std::make_tuple(400, std::string("invalid_parameter"), std::string("turbidity")));
  EXPECT_EQ(refusal([&] {
              check_evaluation_fit(db, {{"fit", id}, {"turbidity", 3}}, both);
            }),
            std::make_tuple(400, std::string("conflicting_parameters"), std::string("turbidity")));
  // The type is checked with the other parameters, where no database is needed.
  for (const nlohmann::json& bad :
       {nlohmann::json(1.5), nlohmann::json(true), nlohmann::json("newest"), nlohmann::json(0)}) {
    EXPECT_EQ(refusal([&] {
                parse_evaluation_parameters({{"fit", bad}}, both);
              }),
              std::make_tuple(400, std::string("invalid_parameter"), std::string("fit")))
        << bad;
  }
  EXPECT_EQ(parse_evaluation_parameters({{"fit", "latest"}}, both),
            nlohmann::json({{"fit", "latest"}}));
}

TEST_F(EvaluationFit, ARunRecordsTheFitAndAnswersAsItsValuesGivenExplicitly) {
  const std::int64_t id = store_fit(db, dataset, "preetham", {{"turbidity", 3.25}});
  const auto [by_fit, rmse_by_fit] = run({{"fit", id}});
  const auto [explicit_values, rmse_explicit] = run({{"turbidity", 3.25}});
  EXPECT_EQ(by_fit, nlohmann::json({{"fit", id}, {"turbidity", 3.25}}));
  EXPECT_EQ(explicit_values, nlohmann::json({{"turbidity", 3.25}}));
  EXPECT_EQ(rmse_by_fit, rmse_explicit);
}

TEST_F(EvaluationFit, LatestIsExpandedWhenTheRunStarts) {
  // As a job's successive runs: a fit stored between two runs is what the next one uses.
  const std::int64_t first = store_fit(db, dataset, "preetham", {{"turbidity", 3.0}});
  const auto [before, rmse_before] = run({{"fit", "latest"}});
  EXPECT_EQ(before, nlohmann::json({{"fit", first}, {"turbidity", 3.0}}));
  const std::int64_t refit = store_fit(db, dataset, "preetham", {{"turbidity", 3.4}});
  const auto [after, rmse_after] = run({{"fit", "latest"}});
  EXPECT_EQ(after, nlohmann::json({{"fit", refit}, {"turbidity", 3.4}}));
  EXPECT_LT(rmse_after, rmse_before);  // 3.4 is the dataset's own turbidity
}

}  // namespace
}  // namespace clearsky::api
