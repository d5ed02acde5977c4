// Tests of a job that re-fits its dataset at each occurrence (server/scheduler/scheduler.h,
// api/jobs/job_refit.h, docs/data-api.md "Jobs"), with real components: a dataset Preetham made
// at turbidity 3.4, the fit runner of POST /v1/fits and the evaluation pool. Two occurrences
// store two fits, each finding the turbidity back, and two evaluations, each recording its own
// fit; the job shows the newest fit next to its last result. A fit that fails fails its
// occurrence: the fit reads failed with its error, and nothing is evaluated.
#include <gtest/gtest.h>

#include <set>

#include "api/fits/fits_api.h"
#include "api/jobs/jobs_api.h"
#include "models/registry.h"
#include "server/scheduler/scheduler.h"
#include "storage/repositories/evaluation_run_repository.h"
#include "storage/repositories/fit_repository.h"
#include "storage/schema/migrations.h"
#include "tests/support/model_made_dataset.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

constexpr std::int64_t kT0 = 1795258800;  // 2026-11-21T11:00:00Z

struct Fixture {
  clearsky::testing::TempDir dir;
  std::filesystem::path file = dir.path / "db.sqlite";
  storage::Database db = storage::open_database(file);
  api::EvaluationPool::OpenDatabase opener = [path = file] { return storage::open_database(path); };
  std::int64_t dataset = 0;
  Fixture() {
    ModelConfig truth;
    truth.atmosphere.turbidity = 3.4;
    dataset = clearsky::testing::store_model_made_dataset(
        db, "made", "preetham", truth, {{30.0, 120.0}, {45.0, 100.0}, {22.0, 170.0}});
  }
  std::int64_t refit_job() {
    return api::create_job(db,
                           R"({"name": "refit-hourly", "schedule": "0 * * * *",
                               "dataset": "made", "models": ["preetham"],
                               "refit": {"model": "preetham", "free": ["turbidity"],
                                         "bounds": {"turbidity": [2, 6]}}})",
                           registered_models(), kT0)
        .body["id"];
  }
  std::vector<storage::RunRecord> runs_of(std::int64_t job_id) {
    std::vector<storage::RunRecord> runs;
    for (auto& run : storage::EvaluationRunRepository(db).list(dataset))
      if (run.job_id == job_id) runs.push_back(std::move(run));
    return runs;
  }
};

// One occurrence at the given time, followed to its end: the fit, then its evaluation.
void run_occurrence(Scheduler& scheduler, api::EvaluationPool& pool, std::int64_t now) {
  EXPECT_EQ(scheduler.tick(now).started, 1);
  scheduler.wait_for_fits();
  pool.wait_idle();
  EXPECT_TRUE(scheduler.in_flight().empty());
}

TEST(JobRefitScheduler, EachOccurrenceFitsThenEvaluatesWithThatFit) {
  Fixture f;
  const std::int64_t id = f.refit_job();
  api::EvaluationPool pool(f.opener, registered_models());
  Scheduler scheduler(f.opener, pool, "test");
  run_occurrence(scheduler, pool, kT0 + 3600);      // 12:00
  run_occurrence(scheduler, pool, kT0 + 2 * 3600);  // 13:00

  // Two fits, stored as any fit (GET /v1/fits lists them), each finding the turbidity back.
  const api::ListPage fits = api::list_fits(f.db, api::Parameters("GET /v1/fits"));
  ASSERT_EQ(fits.items.size(), 2u);
  std::set<std::int64_t> fit_ids;
  for (const auto& fit : fits.items) {
    ASSERT_EQ(fit["status"], "succeeded") << fit.dump();
    EXPECT_EQ(fit["dataset"], "made");
    EXPECT_EQ(fit["model"], "preetham");
    EXPECT_NEAR(fit["values"]["turbidity"].get<double>(), 3.4, 0.05);
    fit_ids.insert(fit["id"].get<std::int64_t>());
  }

  // Two evaluations, each recording its own fit and its value.
  const auto runs = f.runs_of(id);
  ASSERT_EQ(runs.size(), 2u);
  std::set<std::int64_t> used;
  for (const auto& run : runs) {
    EXPECT_EQ(run.status, "succeeded");
    const auto parameters = nlohmann::json::parse(run.parameters);
    ASSERT_TRUE(parameters.contains("fit")) << run.parameters;
    used.insert(parameters["fit"].get<std::int64_t>());
    EXPECT_NEAR(parameters["turbidity"].get<double>(), 3.4, 0.05);
    ASSERT_TRUE(run.rmse.has_value());
  }
  EXPECT_EQ(used, fit_ids);

  // The job shows the newest fit next to its last result.
  const auto shown = api::show_job(f.db, id);
  ASSERT_FALSE(shown["last_fit"].is_null());
  EXPECT_EQ(shown["last_fit"]["id"].get<std::int64_t>(), *fit_ids.rbegin());
  EXPECT_EQ(shown["last_fit"]["status"], "succeeded");
  EXPECT_NEAR(shown["last_fit"]["values"]["turbidity"].get<double>(), 3.4, 0.05);
  EXPECT_TRUE(shown["last_fit"]["rmse_after"].is_number());
  EXPECT_TRUE(shown["last_fit"]["error"].is_null());
  ASSERT_EQ(shown["last_result"].size(), 1u);
  EXPECT_EQ(shown["last_result"][0]["status"], "succeeded");
}

TEST(JobRefitScheduler, AFailedFitFailsTheOccurrenceWithoutEvaluating) {
  Fixture f;
  const std::int64_t id = f.refit_job();
  // The dataset loses its captures after the job was checked: the fit has nothing to fit.
  f.db.execute("DELETE FROM captures");
  api::EvaluationPool pool(f.opener, registered_models());
  Scheduler scheduler(f.opener, pool, "test");
  run_occurrence(scheduler, pool, kT0 + 3600);
  const auto shown = api::show_job(f.db, id);
  ASSERT_FALSE(shown["last_fit"].is_null());
  EXPECT_EQ(shown["last_fit"]["status"], "failed");
  EXPECT_TRUE(shown["last_fit"]["values"].is_null());
  EXPECT_NE(shown["last_fit"]["error"].get<std::string>().find("no captures"), std::string::npos)
      << shown["last_fit"];
  EXPECT_TRUE(shown["last_result"].empty());
  EXPECT_TRUE(f.runs_of(id).empty());
  const auto stored = storage::FitRepository(f.db).get(shown["last_fit"]["id"].get<std::int64_t>());
  ASSERT_TRUE(stored.has_value());
  EXPECT_EQ(stored->fit.status, "failed");
}

}  // namespace
}  // namespace clearsky::server
