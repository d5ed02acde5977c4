// Tests of the SQLite RAII layer and the migrations (storage/sqlite/database.h,
// storage/schema/migrations.h).
#include "storage/sqlite/database.h"

#include <gtest/gtest.h>

#include <cmath>

#include "storage/schema/migrations.h"
#include "storage/sqlite/blob.h"
#include "tests/support/temp_dir.h"

namespace clearsky::storage {
namespace {

std::int64_t count(Database& db, const std::string& table) {
  auto q = db.prepare("SELECT COUNT(*) FROM " + table);
  q.step();
  return q.column_int64(0);
}

TEST(Database, TransactionRollsBackUnlessCommitted) {
  Database db = Database::open(":memory:");
  db.execute("CREATE TABLE t (x INTEGER)");
  {
    Transaction t(db);
    db.execute("INSERT INTO t VALUES (1)");
  }
  EXPECT_EQ(count(db, "t"), 0);
  try {
    Transaction t(db);
    db.execute("INSERT INTO t VALUES (2)");
    throw std::runtime_error("failure in the middle");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(count(db, "t"), 0);
  {
    Transaction t(db);
    db.execute("INSERT INTO t VALUES (3)");
    t.commit();
  }
  EXPECT_EQ(count(db, "t"), 1);
}

TEST(Database, ErrorsCarryTheMessage) {
  Database db = Database::open(":memory:");
  try {
    db.execute("SELEC nonsense");
    FAIL();
  } catch (const SqliteError& e) {
    EXPECT_NE(std::string(e.what()).find("syntax error"), std::string::npos) << e.what();
  }
  EXPECT_THROW(db.prepare("SELECT * FROM missing_table"), SqliteError);
}

TEST(Database, BindsAndReadsEveryType) {
  Database db = Database::open(":memory:");
  db.execute("CREATE TABLE t (i INTEGER, d REAL, s TEXT, b BLOB, n REAL)");
  const std::vector<double> values = {1.5, -2.25, 1e-300};
  auto insert = db.prepare("INSERT INTO t VALUES (?, ?, ?, ?, ?)");
  insert.bind(1, std::int64_t{1} << 40)
      .bind(2, 0.125)
      .bind(3, "text")
      .bind_blob(4, encode_doubles(values));
  insert.bind(5, std::nan(""));
  insert.run();
  auto q = db.prepare("SELECT i, d, s, b, n FROM t");
  ASSERT_TRUE(q.step());
  EXPECT_EQ(q.column_int64(0), std::int64_t{1} << 40);
  EXPECT_EQ(q.column_double(1), 0.125);
  EXPECT_EQ(q.column_text(2), "text");
  EXPECT_EQ(decode_doubles(q.column_blob(3)), values);
  EXPECT_TRUE(q.is_null(4));
  EXPECT_TRUE(std::isnan(q.column_double_or_nan(4)));
  EXPECT_FALSE(q.step());
  const std::vector<std::byte> odd(7);
  EXPECT_THROW(decode_doubles(odd), std::runtime_error);
}

TEST(Database, FileDatabasesUseWalAndForeignKeys) {
  clearsky::testing::TempDir dir;
  Database db = open_database(dir.path / "a.db");
  auto mode = db.prepare("PRAGMA journal_mode");
  ASSERT_TRUE(mode.step());
  EXPECT_EQ(mode.column_text(0), "wal");
  auto fk = db.prepare("PRAGMA foreign_keys");
  ASSERT_TRUE(fk.step());
  EXPECT_EQ(fk.column_int64(0), 1);
  EXPECT_THROW(
      db.execute(
          "INSERT INTO captures (dataset_id, label, time_utc_s, utc_offset_minutes, latitude_deg,"
          " longitude_deg, elevation_m, content_hash, source, imported_utc)"
          " VALUES (999, 'x', 0, 0, 0, 0, 0, 'h', 's', 't')"),
      SqliteError);
}

TEST(Migrations, BringAnEmptyDatabaseToTheLatestVersionOnce) {
  clearsky::testing::TempDir dir;
  {
    Database db = Database::open(dir.path / "m.db");
    EXPECT_EQ(db.user_version(), 0);
    EXPECT_EQ(migrate(db), latest_schema_version());
    EXPECT_EQ(db.user_version(), latest_schema_version());
    EXPECT_EQ(migrate(db), 0);
  }
  Database reopened = open_database(dir.path / "m.db");
  EXPECT_EQ(reopened.user_version(), latest_schema_version());
  for (const char* table :
       {"datasets", "captures", "samples", "evaluation_runs", "evaluation_capture_results", "jobs"})
    EXPECT_EQ(count(reopened, table), 0) << table;
}

TEST(Migrations, AFailedMigrationLeavesThePreviousVersion) {
  Database db = Database::open(":memory:");
  const std::vector<std::string_view> steps = {
      "CREATE TABLE a (x INTEGER);", "CREATE TABLE b (y INTEGER); INSERT INTO nowhere VALUES (1);"};
  EXPECT_THROW(migrate(db, steps), SqliteError);
  EXPECT_EQ(db.user_version(), 1);
  EXPECT_THROW(db.prepare("SELECT * FROM b"), SqliteError);  // rolled back with its version
  EXPECT_EQ(count(db, "a"), 0);
}

TEST(Migrations, ANewerDatabaseIsRefused) {
  Database db = Database::open(":memory:");
  db.execute("PRAGMA user_version = " + std::to_string(latest_schema_version() + 1));
  EXPECT_THROW(migrate(db), std::runtime_error);
}

}  // namespace
}  // namespace clearsky::storage
