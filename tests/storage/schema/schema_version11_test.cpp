// Tests of schema version 11 (storage/schema/migrations.cpp, docs/data-api.md "Jobs"): a
// database of version 10 migrates with its jobs re-fitting nothing, and a job's fit request and
// the fit its newest occurrence made are stored and read back through
// storage/repositories/job_repository.h; the fit going (with its dataset) clears the latter.
#include <gtest/gtest.h>

#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/job_repository.h"
#include "storage/schema/migrations.h"
#include "tests/support/database_at_schema_version.h"

namespace clearsky::storage {
namespace {

using clearsky::testing::database_at_schema_version;

std::int64_t insert_fit(Database& db, std::int64_t dataset_id) {
  auto statement = db.prepare(
      "INSERT INTO fits (dataset_id, model_id, model_version, free_parameters, fixed_parameters,"
      " search_options, captures, settings, software_version, status, created_utc)"
      " VALUES (?, 'preetham', '1', '[]', '{}', '{}', '[]', '{}', 'test', 'succeeded', 'x')");
  statement.bind(1, dataset_id);
  statement.run();
  return db.last_insert_rowid();
}

TEST(SchemaVersion11, MigratesAVersion10DatabaseWithItsJobsReFittingNothing) {
  Database db = database_at_schema_version(10);
  db.execute(
      "INSERT INTO datasets (name, format, created_utc) VALUES ('rhodes', 'kider2014', 'x');"
      "INSERT INTO jobs (name, schedule, dataset_id, models, parameters, paused, created_utc)"
      " VALUES ('hourly', '0 * * * *', 1, 'all', '', 0, 'x')");
  EXPECT_EQ(migrate(db), latest_schema_version() - 10);
  EXPECT_GE(latest_schema_version(), 11);
  const auto jobs = JobRepository(db).list();
  ASSERT_EQ(jobs.size(), 1u);
  EXPECT_EQ(jobs[0].refit, "");
  EXPECT_FALSE(jobs[0].last_fit_id.has_value());
  EXPECT_FALSE(db.prepare("PRAGMA foreign_key_check").step());
}

TEST(SchemaVersion11, AJobKeepsItsFitRequestAndLastFitUntilTheFitGoes) {
  Database db = database_at_schema_version(latest_schema_version());
  const std::int64_t dataset = DatasetRepository(db).find_or_create("made", "kider2014");
  JobRecord job;
  job.name = "refit";
  job.schedule = "0 * * * *";
  job.dataset_id = dataset;
  job.models = "preetham";
  job.refit = R"({"model":"preetham"})";
  JobRepository jobs(db);
  const std::int64_t id = jobs.create(job);
  EXPECT_EQ(jobs.get(id)->refit, job.refit);
  EXPECT_FALSE(jobs.get(id)->last_fit_id.has_value());
  const std::int64_t fit = insert_fit(db, dataset);
  EXPECT_TRUE(jobs.set_last_fit(id, fit));
  EXPECT_EQ(jobs.get(id)->last_fit_id, fit);
  EXPECT_FALSE(jobs.set_last_fit(id + 1, fit));
  db.execute("DELETE FROM fits");
  EXPECT_FALSE(jobs.get(id)->last_fit_id.has_value());
}

}  // namespace
}  // namespace clearsky::storage
