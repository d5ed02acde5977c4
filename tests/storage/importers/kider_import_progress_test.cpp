// Tests of nested archives and progress (storage/importers/kider_reader.h, kider_importer.h):
// a tar of two published .7z captures reads as the two captures, with the same content as
// the .7z files read directly; progress counts only grow, reach the archive's size and entry
// count, and the writing phase reports the captures and samples added; a folder's totals are
// known from the start; an archive holding no capture is refused before the dataset exists.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "storage/importers/kider_importer.h"
#include "storage/importers/kider_reader.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/schema/migrations.h"
#include "tests/storage/importers/tar_writer.h"
#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

namespace clearsky::storage {
namespace {

const char* kRadiance = "kider2014/2013-05-27/RADIANCE";

std::string bytes_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

std::filesystem::path archive(const std::string& time) {
  return clearsky::testing::shared_data_dir() / kRadiance / ("2013-05-27___" + time + ".00.7z");
}

TEST(KiderImportProgress, TarOfPublishedArchivesReadsAsTheirCaptures) {
  CLEARSKY_REQUIRE_SHARED_DATA(kRadiance);
  clearsky::testing::TempDir dir;
  const auto tar = dir.path / "two.tar";
  testing::write_tar(tar, {{"a/2013-05-27___09.30.00.7z", bytes_of(archive("09.30"))},
                           {"README.txt", "not a capture"},
                           {"2013-05-27___09.45.00.7z", bytes_of(archive("09.45"))}});
  std::vector<KiderReadProgress> seen;
  const auto files =
      read_kider_raw_files(tar, [&](const KiderReadProgress& p) { seen.push_back(p); });
  EXPECT_EQ(files.size(), 162u);  // 81 radiance files per capture
  EXPECT_EQ(files.front().path.rfind("2013-05-27___09.45.00.7z/", 0), 0u) << files.front().path;

  ASSERT_GE(seen.size(), 3u);
  for (std::size_t i = 1; i < seen.size(); ++i) {
    EXPECT_GE(seen[i].bytes_read, seen[i - 1].bytes_read);
    EXPECT_GE(seen[i].entries_read, seen[i - 1].entries_read);
    EXPECT_GE(seen[i].files_read, seen[i - 1].files_read);
  }
  const KiderReadProgress& end = seen.back();
  EXPECT_EQ(end.files_read, 162);
  EXPECT_EQ(end.bytes_total, static_cast<std::int64_t>(std::filesystem::file_size(tar)));
  EXPECT_EQ(end.bytes_read, end.bytes_total);
  // 3 entries of the tar and the 81 members of each .7z.
  EXPECT_EQ(end.entries_read, 3 + 162);
  EXPECT_EQ(end.entries_total, end.entries_read);
  EXPECT_EQ(seen.front().entries_total, -1);  // unknown until the end

  const auto from_tar = decode_kider_files(files, tar.string());
  const auto direct = read_kider_archive(archive("09.45"));
  ASSERT_EQ(from_tar.size(), 2u);
  ASSERT_EQ(direct.size(), 1u);
  EXPECT_EQ(from_tar[1].label, "2013-05-27___09.45.00");
  EXPECT_EQ(capture_content_hash(from_tar[1]), capture_content_hash(direct[0]));
}

TEST(KiderImportProgress, ImportReportsReadingThenWriting) {
  CLEARSKY_REQUIRE_SHARED_DATA(kRadiance);
  clearsky::testing::TempDir dir;
  const auto tar = dir.path / "two.tar";
  testing::write_tar(tar, {{"2013-05-27___10.00.00.7z", bytes_of(archive("10.00"))},
                           {"2013-05-27___10.15.00.7z", bytes_of(archive("10.15"))}});
  Database db = open_database(dir.path / "sky.db");
  KiderImportRequest request;
  request.dataset_name = "pair";
  request.paths = {tar};
  std::vector<ImportProgress> seen;
  request.progress = [&](const ImportProgress& p) { seen.push_back(p); };
  const ImportReport report = import_kider(db, request);
  ASSERT_EQ(report.added.size(), 2u);
  ASSERT_GE(seen.size(), 4u);
  EXPECT_EQ(seen.front().phase, "reading");
  EXPECT_EQ(seen.back().phase, "committed");
  EXPECT_EQ(seen.back().captures_added, 2);
  EXPECT_EQ(seen.back().samples_added, 162);
  EXPECT_EQ(seen.back().files_read, 162);
  EXPECT_EQ(seen.back().bytes_read, seen.back().bytes_total);
  int writing = 0;
  for (const ImportProgress& p : seen) writing += p.phase == "writing";
  EXPECT_EQ(writing, 3);  // once before the first capture, then after each
}

TEST(KiderImportProgress, FolderTotalsAreKnownFromTheStart) {
  clearsky::testing::TempDir dir;
  std::filesystem::create_directories(dir.path / "f");
  for (int i = 0; i < 81; ++i) {
    std::ofstream out(
        dir.path / "f" /
        ("2013-05-27___14.00.00_-_" + std::to_string(i) + "____0.0___12.1151.asd.rad.txt"));
    out << "Wavelength\tx\n";
    for (int w = 350; w <= 2500; ++w) out << w << "\t0.1\n";
  }
  std::vector<KiderReadProgress> seen;
  read_kider_raw_files(dir.path / "f", [&](const KiderReadProgress& p) { seen.push_back(p); });
  ASSERT_EQ(seen.size(), 81u);
  EXPECT_EQ(seen.front().entries_total, 81);
  EXPECT_EQ(seen.front().entries_read, 1);
  EXPECT_EQ(seen.back().bytes_read, seen.back().bytes_total);
  EXPECT_GT(seen.back().bytes_total, 81 * 2151 * 4);
}

TEST(KiderImportProgress, AnArchiveWithoutCapturesCreatesNothing) {
  clearsky::testing::TempDir dir;
  const auto tar = dir.path / "none.tar";
  testing::write_tar(tar, {{"notes.txt", "no capture here"}});
  Database db = open_database(dir.path / "sky.db");
  KiderImportRequest request;
  request.dataset_name = "empty";
  request.paths = {tar};
  EXPECT_THROW(import_kider(db, request), std::runtime_error);
  EXPECT_FALSE(DatasetRepository(db).find("empty"));
}

}  // namespace
}  // namespace clearsky::storage
