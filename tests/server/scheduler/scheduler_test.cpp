// Tests of the job scheduler (server/scheduler/scheduler.h) with simulated time: a due job
// runs once and gets its next run, downtime is caught up at most once, a job still running is
// not started again, paused jobs wait, and a new scheduler on the same database file (a
// restart) runs a job that fell due during the downtime exactly once; a job on a broadband
// irradiance series evaluates it at each occurrence, and its history lists the runs with their
// per-component results.
#include "server/scheduler/scheduler.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "api/evaluation/broadband_evaluation.h"
#include "api/evaluation/evaluations_api.h"
#include "api/jobs/jobs_api.h"
#include "models/registry.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/evaluation_run_repository.h"
#include "storage/repositories/irradiance_sample_repository.h"
#include "storage/schema/migrations.h"
#include "tests/models/evaluation/function_model.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

double sky(const ViewDirection&, double) { return 0.05; }

const ModelDescriptor& slow_descriptor() {
  static const ModelDescriptor d = [] {
    ModelDescriptor x = testing::test_descriptor();
    x.id = "slow";
    return x;
  }();
  return d;
}

const std::vector<ModelFactory>& factories() {
  static const std::vector<ModelFactory> f = {
      {&testing::test_descriptor(),
       [](const ModelConfig& c, const PrecomputeContext&) -> std::shared_ptr<const SkyModel> {
         return std::make_shared<testing::FunctionModel>(sky, c);
       }},
      {&slow_descriptor(),
       [](const ModelConfig& c, const PrecomputeContext&) -> std::shared_ptr<const SkyModel> {
         std::this_thread::sleep_for(std::chrono::milliseconds(400));
         return std::make_shared<testing::FunctionModel>(sky, c, slow_descriptor());
       }},
  };
  return f;
}

constexpr std::int64_t kT0 = 1795258800;  // 2026-11-21T11:00:00Z

struct Fixture {
  clearsky::testing::TempDir dir;
  std::filesystem::path file = dir.path / "db.sqlite";
  storage::Database db = storage::open_database(file);
  api::EvaluationPool::OpenDatabase opener = [path = file] { return storage::open_database(path); };
  Fixture() {
    const auto dataset = storage::DatasetRepository(db).find_or_create("synthetic", "kider2014");
    MeasuredCapture c = testing::synthetic_capture(sky);
    storage::CaptureRepository(db).insert(dataset, c, "hash", "test");
  }
  std::int64_t job(const std::string& schedule, const std::string& model = "test-model") {
    return api::create_job(db,
                           R"({"name": ")" + schedule + model + R"(", "schedule": ")" + schedule +
                               R"(", "dataset": "synthetic", "models": [")" + model + R"("]})",
                           factories(), kT0)
        .body["id"];
  }
  std::size_t runs_of(std::int64_t job_id) {
    std::size_t n = 0;
    for (const auto& r : storage::EvaluationRunRepository(db).list(1)) n += r.job_id == job_id;
    return n;
  }
  storage::JobRecord record(std::int64_t id) { return *storage::JobRepository(db).get(id); }
};

TEST(Scheduler, DueJobRunsOnceAndGetsItsNextRun) {
  Fixture f;
  const std::int64_t id = f.job("*/5 * * * *");
  api::EvaluationPool pool(f.opener, factories());
  Scheduler scheduler(f.opener, pool, "test");
  EXPECT_EQ(scheduler.tick(kT0 + 60).started, 0);  // due at 11:05
  EXPECT_EQ(scheduler.tick(kT0 + 300).started, 1);
  pool.wait_idle();
  EXPECT_EQ(scheduler.tick(kT0 + 300).started, 0);  // claimed: not again in the same minute
  EXPECT_EQ(f.runs_of(id), 1u);
  EXPECT_EQ(*f.record(id).last_run_utc, "2026-11-21T11:05:00Z");
  EXPECT_EQ(*f.record(id).next_run_utc, "2026-11-21T11:10:00Z");
  // The run is the job's last result.
  const auto shown = api::show_job(f.db, id);
  ASSERT_EQ(shown["last_result"].size(), 1u);
  EXPECT_EQ(shown["last_result"][0]["status"], "succeeded");
  EXPECT_NEAR(shown["last_result"][0]["rmse"].get<double>(), 0.0, 1e-9);
}

TEST(Scheduler, DowntimeIsCaughtUpAtMostOnce) {
  Fixture f;
  const std::int64_t id = f.job("*/5 * * * *");
  api::EvaluationPool pool(f.opener, factories());
  Scheduler scheduler(f.opener, pool, "test");
  // Three hours later: 36 occurrences were missed; one run, then the next from now.
  const TickReport report = scheduler.tick(kT0 + 3 * 3600 + 30);
  EXPECT_EQ(report.started, 1);
  pool.wait_idle();
  EXPECT_EQ(scheduler.tick(kT0 + 3 * 3600 + 59).started, 0);
  EXPECT_EQ(f.runs_of(id), 1u);
  EXPECT_EQ(*f.record(id).next_run_utc, "2026-11-21T14:05:00Z");
}

TEST(Scheduler, AJobStillRunningIsNotStartedAgain) {
  Fixture f;
  const std::int64_t id = f.job("* * * * *", "slow");
  api::EvaluationPool pool(f.opener, factories(), {2, 8, 1});
  Scheduler scheduler(f.opener, pool, "test");
  EXPECT_EQ(scheduler.tick(kT0 + 60).started, 1);
  // The next minute falls due while the first run (400 ms) is still going.
  const TickReport second = scheduler.tick(kT0 + 120);
  EXPECT_EQ(second.started, 0);
  EXPECT_EQ(second.skipped_running, 1);
  EXPECT_EQ(scheduler.in_flight().count(id), 1u);
  // The skipped occurrence is counted on the job, with its time (GET /v1/jobs/{id}).
  EXPECT_EQ(f.record(id).skipped_count, 1);
  EXPECT_EQ(f.record(id).last_skipped_utc, std::optional<std::string>("2026-11-21T11:02:00Z"));
  const auto shown = api::show_job(f.db, id);
  EXPECT_EQ(shown["skipped_count"], 1);
  EXPECT_EQ(shown["last_skipped"], "2026-11-21T11:02:00Z");
  pool.wait_idle();
  EXPECT_TRUE(scheduler.in_flight().empty());
  EXPECT_EQ(scheduler.tick(kT0 + 180).started, 1);
  pool.wait_idle();
  EXPECT_EQ(f.runs_of(id), 2u);
  EXPECT_EQ(f.record(id).skipped_count, 1);
}

TEST(Scheduler, PausedJobsWait) {
  Fixture f;
  const std::int64_t id = f.job("* * * * *");
  api::pause_job(f.db, id);
  api::EvaluationPool pool(f.opener, factories());
  Scheduler scheduler(f.opener, pool, "test");
  EXPECT_EQ(scheduler.tick(kT0 + 600).started, 0);
  EXPECT_EQ(f.runs_of(id), 0u);
}

TEST(Scheduler, AJobDueDuringDowntimeRunsOnceAfterRestart) {
  Fixture f;
  const std::int64_t id = f.job("0 12 * * *");
  {
    api::EvaluationPool pool(f.opener, factories());
    Scheduler scheduler(f.opener, pool, "test");
    EXPECT_EQ(scheduler.tick(kT0 + 600).started, 0);  // 11:10, due at 12:00
  }                                                   // stopped; 12:00 passes while down
  for (int restart = 0; restart < 2; ++restart) {
    api::EvaluationPool pool(f.opener, factories());
    Scheduler scheduler(f.opener, pool, "test");
    scheduler.tick(kT0 + 2 * 3600);  // 13:00
    pool.wait_idle();
  }
  EXPECT_EQ(f.runs_of(id), 1u);
  EXPECT_EQ(*f.record(id).next_run_utc, "2026-11-22T12:00:00Z");
}

TEST(Scheduler, AnUnreadableNextRunIsRecomputedNotRun) {
  Fixture f;
  const std::int64_t id = f.job("0 * * * *");
  storage::JobRepository(f.db).set_next_run(id, std::string("soon"));
  api::EvaluationPool pool(f.opener, factories());
  Scheduler scheduler(f.opener, pool, "test");
  EXPECT_EQ(scheduler.tick(kT0 + 600).started, 0);
  EXPECT_EQ(*f.record(id).next_run_utc, "2026-11-21T12:00:00Z");
}

TEST(Scheduler, AJobOnABroadbandSeriesEvaluatesItAtEachOccurrence) {
  Fixture f;
  // Noon EDT at Rhodes Hall, GHI as Nishita 1993 gives it there at its defaults.
  storage::IrradianceSample s;
  s.time_utc_s = 1369670400.0;
  s.utc_offset_minutes = -240;
  s.latitude_deg = 42.443449;
  s.longitude_deg = -76.481962;
  s.elevation_m = 250;
  const auto nishita = find_model("nishita93")->create(ModelConfig{}, {});
  s.ghi_w_m2 = *api::modelled_broadband_irradiance(*nishita, {s})[0].ghi_w_m2;
  storage::IrradianceSampleRepository(f.db).insert(
      storage::DatasetRepository(f.db).find_or_create("roof", "irradiance",
                                                      storage::kBroadbandIrradianceKind),
      {s});
  const std::int64_t id = api::create_job(f.db,
                                          R"({"name": "roof-hourly", "schedule": "0 * * * *",
                                              "dataset": "roof", "models": ["nishita93"]})",
                                          registered_models(), kT0)
                              .body["id"];
  api::EvaluationPool pool(f.opener, registered_models());
  Scheduler scheduler(f.opener, pool, "test");
  EXPECT_EQ(scheduler.tick(kT0 + 3600).started, 1);  // 12:00
  pool.wait_idle();
  EXPECT_EQ(scheduler.tick(kT0 + 2 * 3600).started, 1);  // 13:00
  pool.wait_idle();
  api::Parameters query("GET /v1/evaluations");
  query.add("job", std::to_string(id));
  const api::ListPage history = api::list_evaluations(f.db, api::parse_evaluation_filter(query));
  ASSERT_EQ(history.items.size(), 2u);
  for (const auto& run : history.items) {
    EXPECT_EQ(run["status"], "succeeded");
    EXPECT_EQ(run["rmse_unit"], "W/m2");
    ASSERT_EQ(run["irradiance_components"].size(), 1u);
    EXPECT_EQ(run["irradiance_components"][0]["component"], "ghi");
    EXPECT_NEAR(run["irradiance_components"][0]["rmse_w_m2"].get<double>(), 0.0, 1e-9);
  }
  const auto shown = api::show_job(f.db, id);
  ASSERT_EQ(shown["last_result"].size(), 1u);
  EXPECT_NEAR(shown["last_result"][0]["rmse"].get<double>(), 0.0, 1e-9);
}

TEST(Scheduler, StartAndStopTheThread) {
  Fixture f;
  api::EvaluationPool pool(f.opener, factories());
  Scheduler scheduler(f.opener, pool, "test");
  scheduler.start();
  scheduler.stop();
  scheduler.stop();
  SUCCEED();
}

}  // namespace
}  // namespace clearsky::server
