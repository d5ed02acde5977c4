// Tests of reading Kider captures from the published .7z archives and from folders
// (storage/importers/kider_reader.h), on the Kider 2014 captures (README.md "Data").
#include "storage/importers/kider_reader.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <fstream>

#include "models/core/numeric.h"
#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

namespace clearsky::storage {
namespace {

const char* kArchive = "kider2014/2013-05-27/RADIANCE/2013-05-27___09.30.00.7z";

const MeasuredSample& by_index(const MeasuredCapture& c, int index) {
  for (const auto& s : c.samples)
    if (s.index == index) return s;
  throw std::out_of_range("no sample");
}

TEST(KiderReader, ReadsAPublishedArchive) {
  CLEARSKY_REQUIRE_SHARED_DATA(kArchive);
  const auto captures = read_kider_archive(clearsky::testing::shared_data_dir() / kArchive);
  ASSERT_EQ(captures.size(), 1u);
  const MeasuredCapture& c = captures[0];
  EXPECT_EQ(c.label, "2013-05-27___09.30.00");
  EXPECT_EQ(c.samples.size(), 81u);
  EXPECT_EQ(local_time_iso8601(c), "2013-05-27T09:30:00-04:00");
  // Values as in the files: sample 42 (file azimuth 195, elevation 33.749) and sample 0.
  const MeasuredSample& s42 = by_index(c, 42);
  EXPECT_DOUBLE_EQ(s42.radiance.at(350, OutOfRange::error), 5.70084191858768E-02);
  EXPECT_DOUBLE_EQ(s42.radiance.at(351, OutOfRange::error), 5.79518042504787E-02);
  EXPECT_NEAR(s42.view.azimuth_rad, 165.0 * kDegree, 1e-12);
  EXPECT_NEAR(s42.view.zenith_rad, (90.0 - 33.749) * kDegree, 1e-12);
  const MeasuredSample& s0 = by_index(c, 0);
  EXPECT_DOUBLE_EQ(s0.radiance.at(350, OutOfRange::error), 5.62883950769901E-02);
  EXPECT_DOUBLE_EQ(s0.radiance.at(351, OutOfRange::error), 0.057501744478941);
  EXPECT_EQ(s0.quality_flags, kSampleKnownDefective);
  EXPECT_DOUBLE_EQ(s0.radiance.min_nm(), 350.0);
  EXPECT_DOUBLE_EQ(s0.radiance.max_nm(), 2500.0);
}

TEST(KiderReader, ArchivesWithRawFilesKeepOnlyRadiance) {
  // The 10:30 archive also holds the 81 raw .asd.txt files.
  const char* archive = "kider2014/2013-05-27/RADIANCE/2013-05-27___10.30.00.7z";
  CLEARSKY_REQUIRE_SHARED_DATA(archive);
  const auto captures = read_kider_archive(clearsky::testing::shared_data_dir() / archive);
  ASSERT_EQ(captures.size(), 1u);
  EXPECT_EQ(captures[0].samples.size(), 81u);
}

TEST(KiderReader, TruncatedArchiveIsRefused) {
  CLEARSKY_REQUIRE_SHARED_DATA(kArchive);
  clearsky::testing::TempDir dir;
  const auto source = clearsky::testing::shared_data_dir() / kArchive;
  std::ifstream in(source, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto truncated = dir.path / "truncated.7z";
  std::ofstream(truncated, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
  try {
    read_kider_archive(truncated);
    FAIL() << "truncated archive accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("truncated.7z"), std::string::npos) << e.what();
  }
}

TEST(KiderReader, FolderWithAMalformedFileIsRefusedNamingFileAndLine) {
  clearsky::testing::TempDir dir;
  const auto folder = dir.path / "2013-05-27___09.30.00";
  std::filesystem::create_directories(folder);
  for (int i = 0; i < 81; ++i) {
    std::ofstream out(folder / ("2013-05-27___09.30.00_-_" + std::to_string(i) +
                                "____0.0___12.1151.asd.rad.txt"));
    out << "Wavelength\tx\n";
    for (int w = 350; w <= 2500; ++w)
      out << w << "\t" << (i == 7 && w == 500 ? "x" : "0.1") << "\n";
  }
  try {
    read_kider_path(dir.path);
    FAIL() << "malformed file accepted";
  } catch (const KiderFormatError& e) {
    EXPECT_EQ(e.line(), 152);
    EXPECT_NE(std::string(e.what()).find("_-_7____"), std::string::npos) << e.what();
  }
}

TEST(KiderReader, MissingPathIsAnError) {
  EXPECT_THROW(read_kider_path("/nonexistent/kider"), std::runtime_error);
}

// A folder of one regular radiance file, a link named like one leading out of the folder, and
// a fifo named like one (opened without blocking, so a fifo with no writer cannot hold an import).
struct FolderWithTraps {
  clearsky::testing::TempDir dir;
  std::filesystem::path root = dir.path / "root";
  FolderWithTraps() {
    std::filesystem::create_directories(root / "capture");
    std::ofstream(dir.path / "secret.txt") << "root:secret\n";
    std::ofstream(root / "capture" / "2013-05-27___12.00.00_-_0____0.0___12.1151.asd.rad.txt")
        << "regular\n";
    std::filesystem::create_symlink(
        dir.path / "secret.txt",
        root / "capture" / "2013-05-27___12.00.00_-_1____11.25___12.1151.asd.rad.txt");
    const auto fifo = root / "capture" / "2013-05-27___12.00.00_-_2____22.5___12.1151.asd.rad.txt";
    EXPECT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    root = std::filesystem::canonical(root);
  }
};

TEST(KiderReader, AConfinedFolderReadFollowsNoLinkOutAndSkipsSpecialFiles) {
  FolderWithTraps f;
  KiderReadRules rules;
  rules.confine_to = f.root;
  const auto files = read_kider_raw_files(f.root / "capture", {}, rules);
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0].bytes, "regular\n");
}

TEST(KiderReader, AnOperatorFolderReadFollowsLinksButSkipsSpecialFiles) {
  // `clearsky import` (the operator's own command) reads what the operator names.
  FolderWithTraps f;
  const auto files = read_kider_raw_files(f.root / "capture");
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[1].bytes, "root:secret\n");
}

TEST(KiderReader, AConfinedArchivePathIsOpenedWithoutFollowingALink) {
  FolderWithTraps f;
  std::filesystem::create_symlink(f.dir.path / "secret.txt", f.root / "link.7z");
  KiderReadRules rules;
  rules.confine_to = f.root;
  EXPECT_THROW(read_kider_raw_files(f.root / "link.7z", {}, rules), std::runtime_error);
  // Outside the root: refused before it is opened.
  EXPECT_THROW(read_kider_raw_files(f.dir.path / "secret.txt", {}, rules), std::runtime_error);
}

TEST(KiderReader, AnArchivePathThatIsAFifoIsRefusedWithoutWaiting) {
  clearsky::testing::TempDir dir;
  const auto fifo = dir.path / "x.7z";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THROW(read_kider_raw_files(fifo), std::runtime_error);
}

}  // namespace
}  // namespace clearsky::storage
