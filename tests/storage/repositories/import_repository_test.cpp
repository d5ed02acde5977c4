// Tests of the imports table (storage/repositories/import_repository.h): the life of an
// import (queued, running, succeeded or failed) with its progress and report, unknown totals
// kept as unknown, start-up failing what a crash left unfinished, newest first.
#include "storage/repositories/import_repository.h"

#include <gtest/gtest.h>

#include "storage/schema/migrations.h"

namespace clearsky::storage {
namespace {

Database fresh() {
  Database db = Database::open(":memory:");
  migrate(db);
  return db;
}

NewImport upload(const std::string& dataset) {
  NewImport n;
  n.dataset = dataset;
  n.format = "kider";
  n.source = "upload";
  n.upload_bytes = 1234;
  return n;
}

TEST(ImportRepository, QueuedRunningSucceeded) {
  Database db = fresh();
  ImportRepository imports(db);
  const std::int64_t id = imports.create(upload("d"));
  auto r = imports.get(id);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, "queued");
  EXPECT_EQ(r->what.upload_bytes, 1234);
  EXPECT_FALSE(r->started_utc);
  EXPECT_TRUE(r->progress.phase.empty());

  imports.start(id);
  r = imports.get(id);
  EXPECT_EQ(r->status, "running");
  ASSERT_TRUE(r->started_utc);
  EXPECT_GE(*r->started_utc, r->created_utc);

  ImportProgress p;
  p.phase = "committed";
  p.bytes_read = p.bytes_total = 999;
  p.entries_read = 300;
  p.entries_total = -1;
  p.files_read = 162;
  p.captures_added = 2;
  p.samples_added = 162;
  imports.succeed(id, p, R"({"dataset":"d"})");
  r = imports.get(id);
  EXPECT_EQ(r->status, "succeeded");
  EXPECT_EQ(r->progress.bytes_total, 999);
  EXPECT_EQ(r->progress.entries_total, -1);
  EXPECT_EQ(r->progress.samples_added, 162);
  EXPECT_EQ(r->report, R"({"dataset":"d"})");
  EXPECT_FALSE(r->error);
  EXPECT_TRUE(r->finished_utc);
}

TEST(ImportRepository, FailedKeepsTheErrorAndStartUpFailsUnfinished) {
  Database db = fresh();
  ImportRepository imports(db);
  const auto failed = imports.create(upload("a"));
  imports.start(failed);
  imports.fail(failed, {}, "invalid_archive", "x.7z: truncated");
  const auto running = imports.create(upload("b"));
  imports.start(running);
  NewImport from_path = upload("c");
  from_path.source = "path";
  from_path.path = "/srv/k.7z";
  from_path.upload_bytes.reset();
  const auto queued = imports.create(from_path);

  EXPECT_EQ(imports.fail_unfinished("interrupted", "interrupted: stopped"), 2);
  EXPECT_EQ(imports.fail_unfinished("interrupted", "again"), 0);
  const auto a = imports.get(failed);
  EXPECT_EQ(a->error_code, "invalid_archive");
  EXPECT_EQ(a->error, "x.7z: truncated");
  for (const auto id : {running, queued}) {
    const auto r = imports.get(id);
    EXPECT_EQ(r->status, "failed");
    EXPECT_EQ(r->error_code, "interrupted");
    EXPECT_TRUE(r->finished_utc);
  }
  const auto list = imports.list();
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[0].id, queued);
  EXPECT_EQ(list[0].what.path, "/srv/k.7z");
  EXPECT_FALSE(list[0].what.upload_bytes);
  EXPECT_EQ(list[2].id, failed);
  EXPECT_EQ(imports.list(1).size(), 1u);
  EXPECT_EQ(imports.list(100, "failed").size(), 3u);
  EXPECT_EQ(imports.list(100, "failed", "b").at(0).id, running);
  EXPECT_TRUE(imports.list(100, "running").empty());
  EXPECT_FALSE(imports.get(99));
}

TEST(ImportRepository, StatusIsChecked) {
  Database db = fresh();
  EXPECT_THROW(db.execute("INSERT INTO imports (dataset, format, source, status, created_utc)"
                          " VALUES ('d', 'kider', 'upload', 'paused', 'x')"),
               SqliteError);
}

}  // namespace
}  // namespace clearsky::storage
