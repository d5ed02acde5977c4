// End-to-end tests of the data commands of the clearsky executable (server/cli/): `import
// kider` (with its progress lines, at a site and clock given), `import sky-radiance`,
// `datasets --json` and `evaluate`, run as a user would, on
// a temporary database.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "models/evaluation/capture_preparation.h"
#include "models/registry.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/schema/migrations.h"
#include "tests/support/shared_data.h"
#include "tests/support/synthetic_kider_zip.h"
#include "tests/support/temp_dir.h"

namespace clearsky {
namespace {

struct Result {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

Result run(const std::string& arguments) {
  const std::string command = std::string(CLEARSKY_BINARY_DIR) + "/clearsky " + arguments + " 2>&1";
  Result result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) result.output += buffer.data();
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// The test's folder, with the database in var/ (which the CLI creates).
struct TempDb {
  clearsky::testing::TempDir temp;
  const std::filesystem::path& dir = temp.path;
  std::string db = (dir / "var" / "sky.db").string();
};

std::string archive(const std::string& time) {
  return (clearsky::testing::shared_data_dir() / "kider2014/2013-05-27/RADIANCE" /
          ("2013-05-27___" + time + ".00.7z"))
      .string();
}

TEST(DataCommands, ImportThenListDatasets) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  ASSERT_TRUE(std::filesystem::exists(std::string(CLEARSKY_BINARY_DIR) + "/clearsky"))
      << "build the clearsky target";
  TempDb t;
  const Result imported =
      run("import kider " + archive("09.30") + " " + archive("09.45") + " --name day --db " + t.db);
  ASSERT_EQ(imported.exit_code, 0) << imported.output;
  EXPECT_NE(imported.output.find("2 captures added (162 samples)"), std::string::npos)
      << imported.output;
  // Progress on stderr: each phase at least once, the last with the totals.
  EXPECT_NE(imported.output.find("import: reading: "), std::string::npos) << imported.output;
  EXPECT_NE(imported.output.find("import: writing: 162 of 162 entries"), std::string::npos)
      << imported.output;
  EXPECT_NE(imported.output.find("import: committed: 162 of 162 entries"), std::string::npos)
      << imported.output;
  EXPECT_NE(imported.output.find("162 files; 2 captures (162 samples) added"), std::string::npos)
      << imported.output;
  // With --json only the report is printed (the output parses whole).
  const Result again = run("import kider " + archive("09.30") + " --name day --json --db " + t.db);
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(nlohmann::json::parse(again.output).at("unchanged").size(), 1u);
  const Result listed = run("datasets --json --db " + t.db);
  ASSERT_EQ(listed.exit_code, 0) << listed.output;
  EXPECT_EQ(nlohmann::json::parse(listed.output),
            nlohmann::json::parse(R"([{"name": "day", "captures": 2, "samples": 162}])"));
}

TEST(DataCommands, ErrorsAreReportedWithExitStatus1) {
  TempDb t;
  const Result no_dataset = run("evaluate --dataset missing --models all --db " + t.db);
  EXPECT_EQ(no_dataset.exit_code, 1);
  EXPECT_NE(no_dataset.output.find("clearsky: "), std::string::npos) << no_dataset.output;
  const Result unknown_model = run("evaluate --dataset missing --models nishita2042 --db " + t.db);
  EXPECT_EQ(unknown_model.exit_code, 1);
  EXPECT_NE(unknown_model.output.find("nishita2042"), std::string::npos) << unknown_model.output;
  // A parameter that none of the requested models takes (docs/data-api.md "Evaluation
  // parameters"), refused before anything is read or run.
  const Result inapplicable =
      run("evaluate --dataset missing --models bruneton --parameters '{\"turbidity\": 3}' --db " +
          t.db);
  EXPECT_EQ(inapplicable.exit_code, 1);
  EXPECT_NE(inapplicable.output.find("turbidity: applies to none of the requested models"),
            std::string::npos)
      << inapplicable.output;
  std::filesystem::create_directories(t.dir);
  const auto bad = t.dir / "bad.7z";
  {
    std::FILE* f = std::fopen(bad.c_str(), "w");
    std::fputs("not an archive", f);
    std::fclose(f);
  }
  const Result bad_import = run("import kider " + bad.string() + " --db " + t.db);
  EXPECT_EQ(bad_import.exit_code, 1);
  EXPECT_NE(bad_import.output.find("bad.7z"), std::string::npos) << bad_import.output;
}

// With the first registered model (when any is registered): the JSON of docs/architecture.md
// "Command line".
TEST(DataCommands, EvaluatePrintsTheContractJson) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  if (registered_models().empty()) GTEST_SKIP() << "no model registered yet";
  TempDb t;
  ASSERT_EQ(run("import kider " + archive("11.45") + " --name one --db " + t.db).exit_code, 0);
  const std::string id = registered_models().front().descriptor->id;
  const Result evaluated = run("evaluate --dataset one --models " + id + " --json --db " + t.db);
  ASSERT_EQ(evaluated.exit_code, 0) << evaluated.output;
  const auto j = nlohmann::json::parse(evaluated.output);
  EXPECT_EQ(j.at("dataset"), "one");
  EXPECT_EQ(j.at("wavelength_range_nm").dump(), "[360,720]");
  const auto& m = j.at("models").at(0);
  EXPECT_EQ(m.at("model"), id);
  EXPECT_GT(m.at("rmse").get<double>(), 0.0);
  EXPECT_EQ(m.at("captures").at(0).at("time"), "2013-05-27T11:45:00-04:00");
  EXPECT_NEAR(m.at("captures").at(0).at("sun_azimuth").get<double>(), 122.265, 0.2);
}

// `import kider --lat --lon --elevation --utc-offset`: the captures are stored at the site and on
// the clock given, their sun from those (docs/measurement-formats.md); an offset out of range is
// a usage error naming the option.
TEST(DataCommands, ImportKiderAtTheSiteAndClockGiven) {
  TempDb t;
  const std::string zip = (t.dir / "capture.zip").string();
  clearsky::testing::write_synthetic_kider_zip(zip);
  const Result imported = run("import kider " + zip + " --name far --db " + t.db +
                              " --lat 48.8566 --lon 2.3522 --elevation 35 --utc-offset +02:00");
  ASSERT_EQ(imported.exit_code, 0) << imported.output;
  storage::Database db = storage::open_database(t.db);
  const auto dataset = storage::DatasetRepository(db).find("far");
  ASSERT_TRUE(dataset);
  const std::vector<storage::StoredCapture> stored =
      storage::CaptureRepository(db).load(dataset->id);
  ASSERT_EQ(stored.size(), 1u);
  MeasuredCapture expected;
  expected.site = {48.8566, 2.3522, 35};
  expected.utc_offset_minutes = 120;
  // 2013-05-27 12:00 local at UTC+02:00 is 10:00 UTC.
  expected.unix_time_utc_s = 1369648800.0;
  compute_sun_position(expected);
  const MeasuredCapture& capture = stored[0].capture;
  EXPECT_EQ(capture.utc_offset_minutes, 120);
  EXPECT_DOUBLE_EQ(capture.unix_time_utc_s, expected.unix_time_utc_s);
  EXPECT_DOUBLE_EQ(capture.site.latitude_deg, 48.8566);
  EXPECT_DOUBLE_EQ(capture.site.elevation_m, 35);
  EXPECT_DOUBLE_EQ(capture.sun_zenith_computed_deg, expected.sun_zenith_computed_deg);
  EXPECT_DOUBLE_EQ(capture.sun_azimuth_computed_deg, expected.sun_azimuth_computed_deg);

  const Result refused =
      run("import kider " + zip + " --name x --db " + t.db + " --utc-offset +15:00");
  EXPECT_NE(refused.exit_code, 0);
  EXPECT_NE(refused.output.find("--utc-offset"), std::string::npos) << refused.output;
}

// `import sky-radiance FILE.csv|FILE.json`: imported whole, or refused naming the column and row.
TEST(DataCommands, ImportSkyRadianceFiles) {
  TempDb t;
  const std::string header =
      "time,latitude,longitude,elevation_m,view_zenith,view_azimuth,wavelength_nm,radiance\n";
  const auto write = [&](const std::string& name, const std::string& text) {
    const std::filesystem::path path = t.dir / name;
    std::ofstream(path) << text;
    return path.string();
  };
  const Result imported =
      run("import sky-radiance " +
          write("sky.csv", header + "2024-06-21T10:00:00+02:00,48.85,2.35,35,30,90,550,0.05\n") +
          " --name open --json --db " + t.db);
  ASSERT_EQ(imported.exit_code, 0) << imported.output;
  EXPECT_EQ(nlohmann::json::parse(imported.output).at("samples_added"), 1);
  const Result refused =
      run("import sky-radiance " +
          write("bad.csv", header + "2024-06-21T10:00:00+02:00,48.85,2.35,35,30,90,550,-1\n") +
          " --name open --db " + t.db);
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.output.find("row 1 (line 2), radiance"), std::string::npos) << refused.output;
  EXPECT_NE(run("import sky-radiance " + write("sky.txt", header) + " --name open --db " + t.db)
                .exit_code,
            0);
}

}  // namespace
}  // namespace clearsky
