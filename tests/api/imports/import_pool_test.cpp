// Tests of imports as background jobs (api/imports/import_pool.h, imports_api.h): an uploaded
// real archive imported on the pool (state, progress, report, spool file removed), a truncated
// one failing with nothing left behind (no dataset, no spool file), the bounded queue
// refusing with 503 while the worker is busy, and start-up failing interrupted imports.
#include "api/imports/import_pool.h"

#include <gtest/gtest.h>

#include <condition_variable>
#include <fstream>
#include <future>
#include <sstream>

#include "api/error/api_error.h"
#include "api/imports/imports_api.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/schema/migrations.h"
#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

namespace clearsky::api {
namespace {

// Query parameters from (name, value) pairs.
Parameters query(const std::vector<std::pair<std::string, std::string>>& pairs) {
  Parameters p("GET /test");
  for (const auto& [name, value] : pairs) p.add(name, value);
  return p;
}

const char* kArchive = "kider2014/2013-05-27/RADIANCE/2013-05-27___11.45.00.7z";

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

storage::NewImport upload_of(const std::string& dataset, std::size_t bytes) {
  storage::NewImport what;
  what.dataset = dataset;
  what.format = "kider";
  what.source = "upload";
  what.upload_bytes = static_cast<std::int64_t>(bytes);
  return what;
}

struct Fixture {
  clearsky::testing::TempDir dir;
  std::filesystem::path db_path = dir.path / "sky.db";
  storage::Database db = storage::open_database(db_path);

  // The spool as the HTTP route leaves it: the whole body written, finished.
  std::pair<std::unique_ptr<UploadSpool>, std::filesystem::path> spool_of(
      const std::string& bytes) {
    auto spool = std::make_unique<UploadSpool>(dir.path / "uploads", 64u << 20);
    spool->append(bytes);
    const std::filesystem::path path = spool->finish();
    return {std::move(spool), path};
  }
};

TEST(ImportPool, UploadImportedInTheBackground) {
  CLEARSKY_REQUIRE_SHARED_DATA(kArchive);
  Fixture f;
  const std::string bytes = file_bytes(clearsky::testing::shared_data_dir() / kArchive);
  ImportPool pool([&f] { return storage::Database::open(f.db_path); });
  auto [spool, spooled] = f.spool_of(bytes);
  ASSERT_TRUE(std::filesystem::exists(spooled));
  const std::int64_t id =
      pool.submit(f.db, upload_of("noon", bytes.size()), spooled, std::move(spool));
  pool.wait_idle();
  EXPECT_FALSE(std::filesystem::exists(spooled));

  const auto shown = show_import(f.db, &pool, id);
  EXPECT_EQ(shown["status"], "succeeded") << shown.dump();
  EXPECT_EQ(shown["location"], "/v1/imports/" + std::to_string(id));
  EXPECT_EQ(shown["upload_bytes"], bytes.size());
  EXPECT_EQ(shown["report"]["added"][0], "2013-05-27___11.45.00");
  EXPECT_EQ(shown["report"]["samples_added"], 81);
  const auto& progress = shown["progress"];
  EXPECT_EQ(progress["phase"], "committed");
  EXPECT_EQ(progress["bytes_read"], bytes.size());
  EXPECT_EQ(progress["bytes_total"], bytes.size());
  EXPECT_EQ(progress["files_read"], 81);
  EXPECT_EQ(progress["captures_added"], 1);
  EXPECT_EQ(progress["samples_added"], 81);
  EXPECT_TRUE(shown["error"].is_null());
  EXPECT_FALSE(shown["timings"]["finished"].is_null());
  EXPECT_GE(shown["timings"]["finished"].get<std::string>(),
            shown["timings"]["started"].get<std::string>());
  const auto dataset = storage::DatasetRepository(f.db).find("noon");
  ASSERT_TRUE(dataset);
  EXPECT_EQ(dataset->samples, 81);
  EXPECT_EQ(list_imports(f.db, &pool, query({{"status", "succeeded"}})).items.size(), 1u);
  EXPECT_EQ(list_imports(f.db, &pool, query({{"dataset", "other"}})).items.size(), 0u);
  EXPECT_THROW(list_imports(f.db, &pool, query({{"colour", "red"}})), ApiError);
}

TEST(ImportPool, TruncatedUploadFailsAndLeavesNothing) {
  CLEARSKY_REQUIRE_SHARED_DATA(kArchive);
  Fixture f;
  std::string bytes = file_bytes(clearsky::testing::shared_data_dir() / kArchive);
  bytes.resize(bytes.size() / 2);
  ImportPool pool([&f] { return storage::Database::open(f.db_path); });
  auto [spool, spooled] = f.spool_of(bytes);
  const std::int64_t id =
      pool.submit(f.db, upload_of("cut", bytes.size()), spooled, std::move(spool));
  pool.wait_idle();
  const auto shown = show_import(f.db, &pool, id);
  EXPECT_EQ(shown["status"], "failed");
  EXPECT_EQ(shown["error"]["code"], "invalid_archive");
  EXPECT_NE(shown["error"]["message"].get<std::string>().find("truncated"), std::string::npos)
      << shown.dump();
  EXPECT_TRUE(shown["report"].is_null());
  EXPECT_FALSE(storage::DatasetRepository(f.db).find("cut"));
  EXPECT_FALSE(std::filesystem::exists(spooled));
  EXPECT_TRUE(std::filesystem::is_empty(f.dir.path / "uploads"));
}

TEST(ImportPool, FullQueueIs503) {
  Fixture f;
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  std::promise<void> busy;
  ImportPool pool(
      [&f, released, &busy] {
        busy.set_value();  // the worker has taken the first import
        released.wait();
        return storage::Database::open(f.db_path);
      },
      ImportPoolOptions{1, 1, {}, {}});
  storage::NewImport missing = upload_of("x", 0);
  missing.source = "path";
  missing.path = (f.dir.path / "absent.7z").string();
  const auto first = pool.submit(f.db, missing, missing.path);
  busy.get_future().wait();
  const auto second = pool.submit(f.db, missing, missing.path);
  try {
    pool.submit(f.db, missing, missing.path);
    ADD_FAILURE() << "a third import was queued";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 503);
    EXPECT_EQ(e.code(), "busy");
  }
  EXPECT_TRUE(pool.live_progress(first));
  EXPECT_FALSE(pool.live_progress(second));
  EXPECT_EQ(show_import(f.db, &pool, second)["status"], "queued");
  EXPECT_TRUE(show_import(f.db, &pool, second)["progress"].is_null());
  release.set_value();
  pool.wait_idle();
  for (const auto id : {first, second}) {
    const auto shown = show_import(f.db, &pool, id);
    EXPECT_EQ(shown["status"], "failed");
    EXPECT_EQ(shown["error"]["code"], "invalid_archive") << shown.dump();
  }
  EXPECT_EQ(list_imports(f.db, &pool, query({})).items.size(), 2u);  // the refused one left no row
}

TEST(ImportPool, StartUpFailsInterruptedImports) {
  Fixture f;
  storage::ImportRepository imports(f.db);
  const auto running = imports.create(upload_of("d", 10));
  imports.start(running);
  EXPECT_EQ(fail_interrupted_imports(f.db), 1);
  const auto shown = show_import(f.db, nullptr, running);
  EXPECT_EQ(shown["status"], "failed");
  EXPECT_EQ(shown["error"]["code"], "interrupted");
  try {
    show_import(f.db, nullptr, running + 1);
    ADD_FAILURE() << "an unknown import was shown";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 404);
  }
}

}  // namespace
}  // namespace clearsky::api
