// Tests of schema version 6 (storage/schema/migrations.cpp): evaluation tickets are stored, a
// database of version 5 migrates with its runs untouched, and ticket ids are never reused.
#include <gtest/gtest.h>

#include "models/core/sky_model.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/evaluation_run_repository.h"
#include "storage/repositories/evaluation_ticket_repository.h"
#include "storage/schema/migrations.h"
#include "tests/support/database_at_schema_version.h"

namespace clearsky::storage {
namespace {

using clearsky::testing::database_at_schema_version;

TEST(SchemaVersion6, MigratesAVersion5DatabaseWithItsRunsUntouched) {
  Database db = database_at_schema_version(5);
  const std::int64_t dataset = DatasetRepository(db).find_or_create("set", "kider2014");
  NewRun run;
  run.dataset_id = dataset;
  run.model_id = "preetham";
  run.model_version = "1";
  run.configuration = ModelConfig{}.canonical_string();
  run.software_version = "t";
  const std::int64_t run_id = EvaluationRunRepository(db).start(run);
  EXPECT_THROW(db.execute("SELECT 1 FROM evaluation_tickets"), SqliteError);

  const auto& all = schema_migrations();
  EXPECT_EQ(migrate(db, std::vector<std::string_view>(all.begin(), all.begin() + 6)), 1);
  EXPECT_EQ(db.user_version(), 6);
  migrate(db);  // the repositories read the latest schema
  const auto kept = EvaluationRunRepository(db).get(run_id);
  ASSERT_TRUE(kept);
  EXPECT_EQ(kept->status, "running");
  EXPECT_EQ(kept->model_id, "preetham");
  EvaluationTicketRepository tickets(db);
  const std::int64_t first = tickets.create("set", std::nullopt, {"preetham"});
  EXPECT_EQ(first, 1);
  EXPECT_FALSE(db.prepare("PRAGMA foreign_key_check").step());
}

TEST(SchemaVersion6, TicketIdsAreNeverReused) {
  Database db = database_at_schema_version(6);
  EvaluationTicketRepository tickets(db);
  const std::int64_t first = tickets.create("set", std::nullopt, {"preetham"});
  const std::int64_t second = tickets.create("set", 7, {"hosek"});
  EXPECT_EQ(second, first + 1);
  db.execute("DELETE FROM evaluation_tickets WHERE id = " + std::to_string(second));
  EXPECT_EQ(tickets.create("set", std::nullopt, {"preetham"}), second + 1);
  EXPECT_FALSE(tickets.get(second));
  const auto kept = tickets.get(first);
  ASSERT_TRUE(kept);
  EXPECT_FALSE(kept->job_id);
}

}  // namespace
}  // namespace clearsky::storage
