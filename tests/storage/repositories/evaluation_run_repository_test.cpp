// Tests of the evaluation-run and job repositories (storage/repositories/): a run is stored
// as running, finished with its per-capture results or failed; jobs are created, paused,
// recorded and deleted; deleting a dataset removes its runs.
#include "storage/repositories/evaluation_run_repository.h"

#include <gtest/gtest.h>

#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/job_repository.h"
#include "storage/schema/migrations.h"
#include "tests/models/evaluation/synthetic_sky.h"

namespace clearsky::storage {
namespace {

struct Fixture {
  Database db = Database::open(":memory:");
  std::int64_t dataset = 0;
  std::int64_t capture = 0;
  Fixture() {
    migrate(db);
    dataset = DatasetRepository(db).find_or_create("set", "kider2014");
    MeasuredCapture c =
        clearsky::testing::synthetic_capture([](const ViewDirection&, double) { return 0.1; });
    c.label = "2013-05-27___09.30.00";
    capture = CaptureRepository(db).insert(dataset, c, "0123456789abcdef", "test");
  }
};

NewRun new_run(std::int64_t dataset) {
  NewRun run;
  run.dataset_id = dataset;
  run.model_id = "preetham";
  run.model_version =
      std::string("1");  // (assigning the literal trips a GCC 12 -Wrestrict false positive)
  run.parameters = R"({"alpha":0.8,"beta":0.04})";
  run.software_version = "0.1.0";
  return run;
}

TEST(EvaluationRunRepository, StoresAFinishedRunWithItsCaptures) {
  Fixture f;
  EvaluationRunRepository runs(f.db);
  const std::int64_t id = runs.start(new_run(f.dataset));
  EXPECT_EQ(runs.get(id)->status, "running");
  runs.finish(id, 88.5, 0.01, 1.5, "sample 0 repaired\nsun azimuth estimated",
              {{f.capture, "", 0, 0, 48.938, 91.142, 88.5, 2511}});
  const auto run = runs.get(id);
  ASSERT_TRUE(run);
  EXPECT_EQ(run->status, "succeeded");
  EXPECT_EQ(run->model_id, "preetham");
  EXPECT_EQ(run->parameters, R"({"alpha":0.8,"beta":0.04})");
  EXPECT_DOUBLE_EQ(*run->rmse, 88.5);
  EXPECT_DOUBLE_EQ(*run->evaluate_seconds, 1.5);
  EXPECT_TRUE(run->finished_utc.has_value());
  ASSERT_EQ(run->captures.size(), 1u);
  EXPECT_EQ(run->captures[0].capture_label, "2013-05-27___09.30.00");
  EXPECT_DOUBLE_EQ(run->captures[0].sun_azimuth_deg, 91.142);
  EXPECT_EQ(run->captures[0].values_compared, 2511);
  EXPECT_EQ(runs.list(f.dataset).size(), 1u);
}

TEST(EvaluationRunRepository, RecordsFailures) {
  Fixture f;
  EvaluationRunRepository runs(f.db);
  const std::int64_t id = runs.start(new_run(f.dataset));
  runs.fail(id, "precomputation cancelled");
  const auto run = runs.get(id);
  EXPECT_EQ(run->status, "failed");
  EXPECT_EQ(*run->error, "precomputation cancelled");
  EXPECT_FALSE(run->rmse.has_value());
}

TEST(EvaluationRunRepository, DeletingTheDatasetDeletesItsRuns) {
  Fixture f;
  EvaluationRunRepository runs(f.db);
  const std::int64_t id = runs.start(new_run(f.dataset));
  runs.finish(id, 1, 0, 0, "", {{f.capture, "", 0, 0, 10, 20, 1, 1}});
  EXPECT_TRUE(DatasetRepository(f.db).remove("set"));
  EXPECT_FALSE(runs.get(id).has_value());
  EXPECT_FALSE(DatasetRepository(f.db).find("set").has_value());
}

TEST(JobRepository, CreatePauseRecordDelete) {
  Fixture f;
  JobRepository jobs(f.db);
  JobRecord job;
  job.name = "nightly";
  job.schedule = "0 3 * * *";
  job.dataset_id = f.dataset;
  job.models = "all";
  const std::int64_t id = jobs.create(job);
  EXPECT_THROW(jobs.create(job), SqliteError);  // name taken
  job.name = "orphan";
  job.dataset_id = 12345;
  EXPECT_THROW(jobs.create(job), SqliteError);  // no such dataset
  EXPECT_TRUE(jobs.set_paused(id, true));
  EXPECT_TRUE(jobs.get(id)->paused);
  EXPECT_TRUE(jobs.record_run(id, "2026-11-21T03:00:00.000Z", "2026-11-22T03:00:00.000Z"));
  EXPECT_EQ(*jobs.get(id)->next_run_utc, "2026-11-22T03:00:00.000Z");
  ASSERT_EQ(jobs.list().size(), 1u);
  EXPECT_TRUE(jobs.remove(id));
  EXPECT_FALSE(jobs.remove(id));
}

TEST(CaptureRepository, RoundTripsCapturesExactly) {
  Fixture f;
  const auto stored = CaptureRepository(f.db).load(f.dataset);
  ASSERT_EQ(stored.size(), 1u);
  const MeasuredCapture original =
      clearsky::testing::synthetic_capture([](const ViewDirection&, double) { return 0.1; });
  ASSERT_EQ(stored[0].capture.samples.size(), original.samples.size());
  for (std::size_t i = 0; i < original.samples.size(); ++i) {
    EXPECT_EQ(stored[0].capture.samples[i].radiance.values(),
              original.samples[i].radiance.values());
    EXPECT_EQ(stored[0].capture.samples[i].view.zenith_rad, original.samples[i].view.zenith_rad);
  }
  EXPECT_EQ(stored[0].capture.sun_zenith_computed_deg, original.sun_zenith_computed_deg);
  CaptureRepository(f.db).set_estimated_sun_azimuth(f.capture, 123.4);
  EXPECT_EQ(CaptureRepository(f.db).load(f.dataset)[0].capture.sun_azimuth_estimated_deg, 123.4);
}

}  // namespace
}  // namespace clearsky::storage
