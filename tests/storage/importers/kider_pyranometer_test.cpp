// The Kider et al. 2014 pyranometer records (storage/importers/kider_pyranometer.h): per-capture
// files on the site's local clock, the day file whose offsets are minutes from its first record,
// its clock taken from the per-capture files (and refused when they disagree), and the
// published 2013-05-27 records.
#include "storage/importers/kider_pyranometer.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

namespace clearsky::storage {
namespace {

void write(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

// 2013-05-27T09:30:00-04:00.
constexpr double kFirstUtcS = 1369661400;

TEST(KiderPyranometer, CaptureFilesAreOnTheSitesLocalClock) {
  clearsky::testing::TempDir dir;
  write(dir.path / "2013.05.27.09.30.00.txt",
        "654.84 2013.05.27.09.30.00\r\n653.23 2013.05.27.09.30.04\r\n");
  const auto read = read_kider_pyranometer({dir.path}, {}, std::nullopt);
  ASSERT_EQ(read.samples.size(), 2u);
  EXPECT_EQ(read.samples[0].time_utc_s, kFirstUtcS);
  EXPECT_EQ(read.samples[1].time_utc_s, kFirstUtcS + 4);
  EXPECT_EQ(read.samples[1].ghi_w_m2, 653.23);
  EXPECT_FALSE(read.samples[1].dhi_w_m2);
  EXPECT_EQ(read.samples[0].utc_offset_minutes, -240);
  EXPECT_DOUBLE_EQ(read.samples[0].latitude_deg, 42.443449);
}

TEST(KiderPyranometer, TheDayFileCountsMinutesFromTheFirstCaptureRecord) {
  clearsky::testing::TempDir dir;
  write(dir.path / "2013.05.27.09.30.00.txt",
        "654.84 2013.05.27.09.30.00\n653.23 2013.05.27.09.30.04\n");
  write(dir.path / "pyranometer_full_day.txt", "0 654.84\n0.0666667 653.23\n240 996.77\n");
  const auto read = read_kider_pyranometer({dir.path}, {}, std::nullopt);
  ASSERT_EQ(read.samples.size(), 3u);
  EXPECT_EQ(read.samples[0].time_utc_s, kFirstUtcS);
  EXPECT_NEAR(read.samples[1].time_utc_s, kFirstUtcS + 4, 1e-3);
  EXPECT_EQ(read.samples[2].time_utc_s, kFirstUtcS + 4 * 3600);
  EXPECT_EQ(read.samples[2].ghi_w_m2, 996.77);

  // Alone it has no clock unless given; with a clock given, that clock.
  EXPECT_THROW(read_kider_pyranometer({dir.path / "pyranometer_full_day.txt"}, {}, std::nullopt),
               std::invalid_argument);
  const auto given = read_kider_pyranometer({dir.path / "pyranometer_full_day.txt"}, {},
                                            std::string("2013-05-27T10:30:00"));
  EXPECT_EQ(given.samples[0].time_utc_s, kFirstUtcS + 3600);
}

TEST(KiderPyranometer, RefusesADayFileThatDoesNotStartWithTheCaptureRecords) {
  clearsky::testing::TempDir dir;
  write(dir.path / "2013.05.27.09.30.00.txt", "654.84 2013.05.27.09.30.00\n");
  write(dir.path / "pyranometer_full_day.txt", "0 700\n");
  EXPECT_THROW(read_kider_pyranometer({dir.path}, {}, std::nullopt), std::invalid_argument);
}

TEST(KiderPyranometer, RefusesMalformedRowsNamingTheFileAndLine) {
  clearsky::testing::TempDir dir;
  write(dir.path / "2013.05.27.09.30.00.txt", "654.84 2013.05.27.09.30.00\n653.23 09:30:04\n");
  try {
    read_kider_pyranometer({dir.path}, {}, std::nullopt);
    FAIL() << "no refusal";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("2013.05.27.09.30.00.txt, line 2"), std::string::npos)
        << e.what();
  }
}

TEST(KiderPyranometer, ThePublishedDayStartsAtTheFirstCapture) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/pyranometer_full_day.txt");
  const auto day = clearsky::testing::shared_data_dir() / "kider2014/2013-05-27";
  const auto captures = read_kider_pyranometer({day / "IRRADIANCE"}, {}, std::nullopt);
  EXPECT_EQ(captures.samples.size(), 1215u);  // 15 files of 81 records
  EXPECT_EQ(captures.samples.front().time_utc_s, kFirstUtcS);
  const auto read = read_kider_pyranometer({day}, {}, std::nullopt);
  ASSERT_GT(read.samples.size(), 3000u);
  EXPECT_EQ(read.samples.front().time_utc_s, kFirstUtcS);
  // The 09:45 capture's first record (696.77 W/m2) is the day file's record at minute 15.
  const auto at_0945 =
      std::find_if(read.samples.begin(), read.samples.end(),
                   [](const IrradianceSample& s) { return s.time_utc_s >= kFirstUtcS + 900; });
  ASSERT_NE(at_0945, read.samples.end());
  EXPECT_NEAR(at_0945->time_utc_s, kFirstUtcS + 900, 0.1);
  EXPECT_EQ(at_0945->ghi_w_m2, 696.77);
}

}  // namespace
}  // namespace clearsky::storage
