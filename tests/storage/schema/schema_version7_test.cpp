// Tests of schema version 7 (storage/schema/migrations.cpp, docs/fits.md "Stored fits"): a
// database of version 6 migrates with its tickets untouched, and fits are stored, listed,
// finished, failed and interrupted through storage/repositories/fit_repository.h.
#include <gtest/gtest.h>

#include <cmath>

#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/evaluation_ticket_repository.h"
#include "storage/repositories/fit_repository.h"
#include "storage/schema/migrations.h"
#include "tests/support/database_at_schema_version.h"

namespace clearsky::storage {
namespace {

using clearsky::testing::database_at_schema_version;

NewFit preetham_fit(std::int64_t dataset) {
  NewFit fit;
  fit.dataset_id = dataset;
  fit.model_id = "preetham";
  fit.model_version = "1";
  fit.free_parameters = R"([{"name":"turbidity","min":2,"max":10,"grid_points":21}])";
  fit.software_version = "t";
  return fit;
}

TEST(SchemaVersion7, MigratesAVersion6DatabaseWithItsTicketsUntouched) {
  Database db = database_at_schema_version(6);
  DatasetRepository(db).find_or_create("set", "kider2014");
  const std::int64_t ticket = EvaluationTicketRepository(db).create("set", 3, {"preetham"});
  EXPECT_THROW(db.execute("SELECT 1 FROM fits"), SqliteError);
  // Every migration after version 6 runs (version 7 added the fits table; later ones follow).
  EXPECT_EQ(migrate(db), latest_schema_version() - 6);
  EXPECT_EQ(db.user_version(), latest_schema_version());
  EXPECT_GE(latest_schema_version(), 7);
  const auto kept = EvaluationTicketRepository(db).get(ticket);
  ASSERT_TRUE(kept);
  EXPECT_EQ(kept->job_id, 3);
  EXPECT_FALSE(db.prepare("PRAGMA foreign_key_check").step());
}

TEST(SchemaVersion7, AFitIsRecordedRunningThenFinished) {
  Database db = database_at_schema_version(7);
  const std::int64_t dataset = DatasetRepository(db).find_or_create("set", "kider2014");
  FitRepository fits(db);
  const std::int64_t id = fits.start(preetham_fit(dataset));
  fits.progress(id, 0.25, "grid");
  auto running = fits.get(id);
  ASSERT_TRUE(running);
  EXPECT_EQ(running->dataset, "set");
  EXPECT_EQ(running->fit.status, "running");
  EXPECT_EQ(running->progress, 0.25);
  EXPECT_EQ(running->stage, "grid");
  EXPECT_FALSE(running->outcome);

  FitOutcome outcome;
  outcome.result = R"({"turbidity":3.4})";
  outcome.rmse_before = 88.7;
  outcome.rmse_search = 40.0;
  outcome.rmse_after = 40.0;
  outcome.timings = R"({"total":1.5})";
  fits.finish(id, outcome);
  const auto done = fits.get(id);
  ASSERT_TRUE(done);
  EXPECT_EQ(done->fit.status, "succeeded");
  ASSERT_TRUE(done->outcome);
  EXPECT_EQ(done->outcome->result, R"({"turbidity":3.4})");
  EXPECT_EQ(done->outcome->rmse_before, 88.7);
  EXPECT_FALSE(done->outcome->cross_validated_rmse);
  EXPECT_TRUE(done->finished_utc);
  // A finished fit is not failed afterwards.
  fits.fail(id, "late");
  EXPECT_EQ(fits.get(id)->fit.status, "succeeded");
}

TEST(SchemaVersion7, ListsNewestFirstAndInterruptsWhatACrashLeft) {
  Database db = database_at_schema_version(7);
  const std::int64_t dataset = DatasetRepository(db).find_or_create("set", "kider2014");
  FitRepository fits(db);
  const std::int64_t a = fits.start(preetham_fit(dataset));
  NewFit queued = preetham_fit(dataset);
  queued.status = "queued";
  const std::int64_t b = fits.start(queued);
  const std::int64_t c = fits.start(preetham_fit(dataset));
  fits.fail(c, "model failed");
  const auto page = fits.list(2);
  ASSERT_EQ(page.size(), 2u);
  EXPECT_EQ(page[0].id, c);
  EXPECT_EQ(page[1].id, b);
  EXPECT_EQ(fits.list(10, b).size(), 1u);
  EXPECT_EQ(fits.interrupt_unfinished("server stopped"), 2);
  EXPECT_EQ(fits.get(a)->fit.status, "interrupted");
  EXPECT_EQ(fits.get(b)->error, "server stopped");
  EXPECT_EQ(fits.get(c)->fit.status, "failed");
  // Ids are never reused.
  db.execute("DELETE FROM fits WHERE id = " + std::to_string(c));
  EXPECT_EQ(fits.start(preetham_fit(dataset)), c + 1);
}

}  // namespace
}  // namespace clearsky::storage
