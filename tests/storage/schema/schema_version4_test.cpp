// Tests of schema version 4 (storage/schema/migrations.cpp): ids never reused, runs keeping
// their job id after the job is deleted, run parameters converted from the configuration key
// that versions 1 to 3 stored (legacy_run_parameters.h) with the key kept for the history.
#include <gtest/gtest.h>

#include "models/core/sky_model.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/evaluation_run_repository.h"
#include "storage/repositories/import_repository.h"
#include "storage/repositories/job_repository.h"
#include "storage/schema/legacy_run_parameters.h"
#include "storage/schema/migrations.h"
#include "tests/models/evaluation/function_model.h"
#include "tests/support/database_at_schema_version.h"

namespace clearsky::storage {
namespace {

using clearsky::testing::database_at_schema_version;

NewRun new_run(std::int64_t dataset, std::optional<std::int64_t> job = std::nullopt) {
  NewRun run;
  run.dataset_id = dataset;
  run.job_id = job;
  run.model_id = "preetham";
  run.model_version = std::string("1");
  run.configuration = ModelConfig{}.canonical_string();
  run.software_version = "t";
  return run;
}

JobRecord job_named(const std::string& name, std::int64_t dataset) {
  JobRecord job;
  job.name = name;
  job.schedule = "0 3 * * *";
  job.dataset_id = dataset;
  job.models = "all";
  return job;
}

TEST(LegacyRunParameters, KeepsWhatDiffersFromTheDefaultsAsShortestNumbers) {
  ModelConfig config;
  EXPECT_EQ(legacy_run_parameters_json(config.canonical_string()), "{}");
  config.atmosphere.turbidity = 3.0;
  config.atmosphere.angstrom_alpha = 1.3;
  config.atmosphere.ground_albedo = 0.2;
  config.options["scattering_orders"] = 4;  // options are kept, even at their default
  EXPECT_EQ(legacy_run_parameters_json(config.canonical_string()),
            R"({"alpha":1.3,"turbidity":3,"albedo":0.2,"scattering_orders":4})");
  config = ModelConfig{};
  config.atmosphere.mie_single_scattering_albedo = 0.9;
  config.atmosphere.rayleigh_scale_height_m = 8500;
  EXPECT_EQ(legacy_run_parameters_json(config.canonical_string()),
            R"({"rayleigh_scale_height_m":8500,"mie_single_scattering_albedo":0.9})");
  for (const char* other : {"", "not a key", "alpha=x", "a b=1"})
    EXPECT_EQ(legacy_run_parameters_json(other), "{}") << other;
}

TEST(SchemaVersion4, ConvertsRunsKeepingTheirResultsAndJobs) {
  Database db = database_at_schema_version(3);
  const std::int64_t dataset = DatasetRepository(db).find_or_create("set", "kider2014");
  const std::int64_t capture = CaptureRepository(db).insert(
      dataset,
      clearsky::testing::synthetic_capture([](const ViewDirection&, double) { return 0.1; }),
      "hash", "test");
  JobRepository(db).create(job_named("nightly", dataset));
  ModelConfig turbid;
  turbid.atmosphere.turbidity = 3.0;
  db.execute(
      "INSERT INTO evaluation_runs (id, dataset_id, job_id, model_id, model_version, parameters,"
      " software_version, min_wavelength_nm, max_wavelength_nm, started_utc, finished_utc,"
      " status, rmse) VALUES (7, " +
      std::to_string(dataset) + ", 1, 'preetham', '1', '" + turbid.canonical_string() +
      "', 'old', 360, 720, '2026-01-01T00:00:00.000Z', '2026-01-01T00:00:01.000Z',"
      " 'succeeded', 88.7);"
      "INSERT INTO evaluation_capture_results (run_id, capture_id, sun_zenith_deg,"
      " sun_azimuth_deg, rmse, values_compared) VALUES (7, " +
      std::to_string(capture) + ", 48.9, 91.1, 88.7, 2511)");
  const auto& all = schema_migrations();
  EXPECT_EQ(migrate(db, std::vector<std::string_view>(all.begin(), all.begin() + 4)), 1);
  EXPECT_EQ(db.user_version(), 4);
  migrate(db);  // the repository reads the latest schema
  EvaluationRunRepository runs(db);
  const auto old = runs.get(7);
  ASSERT_TRUE(old);
  EXPECT_EQ(old->parameters, R"({"turbidity":3})");
  EXPECT_EQ(old->configuration, turbid.canonical_string());
  EXPECT_EQ(old->job_id, 1);
  ASSERT_EQ(old->captures.size(), 1u);  // the rebuild kept the per-capture results
  EXPECT_DOUBLE_EQ(old->captures[0].rmse, 88.7);
  // The history finds the converted run by its configuration.
  NewRun again = new_run(dataset);
  again.configuration = turbid.canonical_string();
  const std::int64_t id = runs.start(again);
  RunCaptureResult same_capture;  // the same samples as the converted run (schema version 5)
  same_capture.capture_id = capture;
  same_capture.rmse = 88.7;
  runs.finish(id, 88.7, 0, 0, "", {same_capture});
  EXPECT_EQ(runs.previous_like(*runs.get(id))->id, 7);
  // Foreign keys are on again and still hold.
  EXPECT_THROW(runs.start(new_run(12345)), SqliteError);
}

TEST(SchemaVersion4, IdsAreNeverReusedAndRunsKeepTheirDeletedJob) {
  Database db = open_database(":memory:");
  const std::int64_t dataset = DatasetRepository(db).find_or_create("set", "kider2014");
  JobRepository jobs(db);
  const std::int64_t job = jobs.create(job_named("nightly", dataset));
  EvaluationRunRepository runs(db);
  const std::int64_t run = runs.start(new_run(dataset, job));
  ASSERT_TRUE(jobs.remove(job));
  // The run keeps its job's id and is found by it.
  EXPECT_EQ(runs.get(run)->job_id, job);
  RunFilter by_job;
  by_job.job_id = job;
  ASSERT_EQ(runs.list(by_job, 10).rows.size(), 1u);
  // The newest job, run and import deleted: the next ones get new ids all the same.
  EXPECT_GT(jobs.create(job_named("nightly", dataset)), job);
  db.execute("DELETE FROM evaluation_runs WHERE id = " + std::to_string(run));
  EXPECT_GT(runs.start(new_run(dataset)), run);
  ImportRepository imports(db);
  NewImport what{"set", "kider", "path", "/srv/a.7z", std::nullopt};
  const std::int64_t import = imports.create(what);
  db.execute("DELETE FROM imports WHERE id = " + std::to_string(import));
  EXPECT_GT(imports.create(what), import);
}

TEST(SchemaVersion4, ListsArePagedByKey) {
  Database db = open_database(":memory:");
  for (const char* name : {"c", "a", "b"}) DatasetRepository(db).find_or_create(name, "kider2014");
  DatasetRepository datasets(db);
  auto first = datasets.list_page(2);
  ASSERT_EQ(first.rows.size(), 2u);
  EXPECT_EQ(first.rows[1].name, "b");
  EXPECT_TRUE(first.more);
  auto last = datasets.list_page(2, first.rows[1].name);
  ASSERT_EQ(last.rows.size(), 1u);
  EXPECT_EQ(last.rows[0].name, "c");
  EXPECT_FALSE(last.more);
  ImportRepository imports(db);
  std::vector<std::int64_t> ids;
  for (const char* d : {"a", "b", "a", "a"})
    ids.push_back(imports.create({d, "kider", "upload", "", 1}));
  // Filtered before the limit: the "a" imports, newest first.
  const auto page = imports.list_page(2, std::nullopt, "a", std::nullopt);
  ASSERT_EQ(page.rows.size(), 2u);
  EXPECT_EQ(page.rows[0].id, ids[3]);
  EXPECT_EQ(page.rows[1].id, ids[2]);
  EXPECT_TRUE(page.more);
  const auto rest = imports.list_page(2, std::nullopt, "a", page.rows[1].id);
  ASSERT_EQ(rest.rows.size(), 1u);
  EXPECT_EQ(rest.rows[0].id, ids[0]);
  EXPECT_FALSE(rest.more);
}

}  // namespace
}  // namespace clearsky::storage
