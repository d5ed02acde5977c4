// Tests of the transactional Kider import (storage/importers/kider_importer.h): a real archive
// gives 81 samples with the file's values, re-import is a no-op, a malformed file, a truncated
// archive and a process killed half-way leave the database exactly as before.
#include "storage/importers/kider_importer.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <string>
#include <vector>

#include "models/core/numeric.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/schema/migrations.h"
#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

namespace clearsky::storage {
namespace {

const char* kRadiance = "kider2014/2013-05-27/RADIANCE";

std::filesystem::path archive(const std::string& time) {
  return clearsky::testing::shared_data_dir() / kRadiance / ("2013-05-27___" + time + ".00.7z");
}

// Everything stored, as text, to compare databases before and after.
std::string snapshot(Database& db) {
  std::string text;
  for (const char* sql :
       {"SELECT id, name, format, created_utc FROM datasets ORDER BY id",
        "SELECT id, label, content_hash, imported_utc FROM captures ORDER BY id",
        "SELECT id, capture_id, scan_index, length(radiance) FROM samples ORDER BY id"}) {
    auto q = db.prepare(sql);
    while (q.step()) {
      for (int c = 0; c < 4; ++c) text += q.column_text(c) + "|";
      text += "\n";
    }
  }
  return text;
}

KiderImportRequest request(std::vector<std::filesystem::path> paths,
                           const std::string& dataset = "kider2014") {
  KiderImportRequest r;
  r.dataset_name = dataset;
  r.paths = std::move(paths);
  return r;
}

void write_folder_capture(const std::filesystem::path& folder, int bad_sample) {
  std::filesystem::create_directories(folder);
  for (int i = 0; i < 81; ++i) {
    std::ofstream out(folder / ("2013-05-27___14.00.00_-_" + std::to_string(i) +
                                "____0.0___12.1151.asd.rad.txt"));
    out << "Wavelength\tx\n";
    for (int w = 350; w <= 2500; ++w)
      out << w << "\t" << (i == bad_sample && w == 360 ? "0.1 0.2" : "0.1") << "\n";
  }
}

TEST(KiderImporter, ImportsARealArchive) {
  CLEARSKY_REQUIRE_SHARED_DATA(kRadiance);
  clearsky::testing::TempDir dir;
  Database db = open_database(dir.path / "sky.db");
  const ImportReport report = import_kider(db, request({archive("09.30")}, "kider"));
  EXPECT_EQ(report.added, std::vector<std::string>{"2013-05-27___09.30.00"});
  EXPECT_EQ(report.samples_added, 81);
  const auto summary = DatasetRepository(db).find("kider");
  ASSERT_TRUE(summary);
  EXPECT_EQ(summary->captures, 1);
  EXPECT_EQ(summary->samples, 81);
  const auto stored = CaptureRepository(db).load(summary->id);
  ASSERT_EQ(stored.size(), 1u);
  const MeasuredCapture& c = stored[0].capture;
  ASSERT_EQ(c.samples.size(), 81u);
  EXPECT_EQ(c.samples[42].index, 42);
  EXPECT_DOUBLE_EQ(c.samples[42].radiance.at(350, OutOfRange::error), 5.70084191858768E-02);
  EXPECT_NEAR(c.samples[42].view.azimuth_rad, 165.0 * kDegree, 1e-12);
  EXPECT_EQ(c.samples[0].quality_flags, kSampleKnownDefective);  // stored as measured
  EXPECT_DOUBLE_EQ(c.samples[0].radiance.at(351, OutOfRange::error), 0.057501744478941);
  EXPECT_NEAR(c.sun_zenith_computed_deg, 48.938, 0.005);
  EXPECT_NEAR(c.sun_azimuth_computed_deg, 98.142, 0.015);
  EXPECT_TRUE(std::isnan(c.sun_azimuth_estimated_deg));
  EXPECT_EQ(stored[0].content_hash, capture_content_hash(c));
}

TEST(KiderImporter, ReimportChangesNothing) {
  CLEARSKY_REQUIRE_SHARED_DATA(kRadiance);
  clearsky::testing::TempDir dir;
  Database db = open_database(dir.path / "sky.db");
  import_kider(db, request({archive("09.30")}));
  const std::string before = snapshot(db);
  const ImportReport again = import_kider(db, request({archive("09.30"), archive("09.30")}));
  EXPECT_TRUE(again.added.empty());
  EXPECT_EQ(again.unchanged.size(), 2u);
  EXPECT_EQ(snapshot(db), before);
}

TEST(KiderImporter, MalformedFileLeavesTheDatabaseUnchanged) {
  CLEARSKY_REQUIRE_SHARED_DATA(kRadiance);
  clearsky::testing::TempDir dir;
  Database db = open_database(dir.path / "sky.db");
  import_kider(db, request({archive("09.30")}));
  const std::string before = snapshot(db);
  write_folder_capture(dir.path / "bad", 12);
  try {
    import_kider(db, request({archive("09.45"), dir.path / "bad"}));
    FAIL() << "malformed file accepted";
  } catch (const KiderFormatError& e) {
    EXPECT_EQ(e.line(), 12);
    EXPECT_NE(std::string(e.what()).find("_-_12____"), std::string::npos) << e.what();
  }
  EXPECT_EQ(snapshot(db), before);
}

TEST(KiderImporter, ArchiveUploadedInMemoryEqualsTheFile) {
  CLEARSKY_REQUIRE_SHARED_DATA(kRadiance);
  clearsky::testing::TempDir dir;
  Database db = open_database(dir.path / "sky.db");
  std::ifstream in(archive("10.15"), std::ios::binary);
  KiderImportRequest upload;
  upload.archives_in_memory.push_back(
      {"upload.7z", std::string((std::istreambuf_iterator<char>(in)), {})});
  const ImportReport first = import_kider(db, upload);
  EXPECT_EQ(first.added, std::vector<std::string>{"2013-05-27___10.15.00"});
  EXPECT_EQ(first.samples_added, 81);
  // The same capture from the file is recognised by its content.
  EXPECT_EQ(import_kider(db, request({archive("10.15")})).unchanged.size(), 1u);
  upload.archives_in_memory[0].bytes.resize(upload.archives_in_memory[0].bytes.size() / 2);
  const std::string before = snapshot(db);
  EXPECT_THROW(import_kider(db, upload), std::runtime_error);
  EXPECT_EQ(snapshot(db), before);
}

TEST(KiderImporter, TruncatedArchiveLeavesTheDatabaseUnchanged) {
  CLEARSKY_REQUIRE_SHARED_DATA(kRadiance);
  clearsky::testing::TempDir dir;
  Database db = open_database(dir.path / "sky.db");
  import_kider(db, request({archive("09.30")}));
  const std::string before = snapshot(db);
  std::ifstream in(archive("10.00"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir.path / "cut.7z", std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size() * 3 / 4));
  EXPECT_THROW(import_kider(db, request({archive("09.45"), dir.path / "cut.7z"})),
               std::runtime_error);
  EXPECT_EQ(snapshot(db), before);
}

TEST(KiderImporter, SameLabelWithOtherContentIsAConflict) {
  clearsky::testing::TempDir dir;
  Database db = open_database(dir.path / "sky.db");
  write_folder_capture(dir.path / "a", -1);
  import_kider(db, request({dir.path / "a"}));
  const std::string before = snapshot(db);
  // Same capture label, one value changed.
  write_folder_capture(dir.path / "b", -1);
  {
    std::ofstream out(dir.path / "b" / "2013-05-27___14.00.00_-_5____0.0___12.1151.asd.rad.txt");
    out << "Wavelength\tx\n";
    for (int w = 350; w <= 2500; ++w) out << w << "\t0.2\n";
  }
  EXPECT_THROW(import_kider(db, request({dir.path / "b"})), std::runtime_error);
  EXPECT_EQ(snapshot(db), before);
}

TEST(KiderImporter, ProcessKilledDuringImportLeavesTheDatabaseAsBefore) {
  CLEARSKY_REQUIRE_SHARED_DATA(kRadiance);
  clearsky::testing::TempDir dir;
  const auto path = dir.path / "sky.db";
  std::string before;
  {
    Database db = open_database(path);
    import_kider(db, request({archive("09.30")}));
    before = snapshot(db);
  }
  const pid_t child = fork();
  ASSERT_NE(child, -1);
  if (child == 0) {
    // The child imports three captures and is killed after writing the second, mid-transaction.
    try {
      Database db = open_database(path);
      KiderImportRequest interrupted =
          request({archive("09.45"), archive("10.00"), archive("10.15")});
      interrupted.after_capture_written = [](int written) {
        if (written == 2) ::kill(::getpid(), SIGKILL);
      };
      import_kider(db, interrupted);
    } catch (...) {
    }
    ::_exit(3);  // not reached when the kill happened
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "child exited with " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
  Database db = open_database(path);
  EXPECT_EQ(snapshot(db), before);
  // And the database still takes the import.
  EXPECT_EQ(import_kider(db, request({archive("09.45")})).added.size(), 1u);
}

TEST(KiderImporter, ANameOutsideTheRuleIsRefusedBeforeAnythingIsRead) {
  clearsky::testing::TempDir dir;
  Database db = open_database(dir.path / "sky.db");
  for (const std::string& name : std::vector<std::string>{"a/b", "../x", std::string(5000, 'a')}) {
    KiderImportRequest request;
    request.dataset_name = name;
    request.paths = {dir.path / "nothing-here"};
    EXPECT_THROW(import_kider(db, request), InvalidDatasetName) << name.substr(0, 10);
  }
}

}  // namespace
}  // namespace clearsky::storage
