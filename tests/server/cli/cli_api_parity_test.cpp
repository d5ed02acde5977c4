// The CLI (offline, `clearsky import kider` and `clearsky evaluate`) and the API path (an uploaded
// archive spooled to disk and imported on the background import pool, an evaluation on the
// background evaluation pool) give identical results on the same captures (docs/architecture.md
// "Storage and durability"): the same import report, and Preetham on two public captures, down to
// the per-sample errors (`clearsky evaluate --json --samples=spectra` against
// GET /v1/evaluations/{id}?samples=spectra).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "api/datasets/upload_spool.h"
#include "api/evaluation/evaluation_pool.h"
#include "api/evaluation/evaluations_api.h"
#include "api/imports/import_pool.h"
#include "api/imports/imports_api.h"
#include "models/registry.h"
#include "storage/schema/migrations.h"
#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

namespace clearsky {
namespace {

std::string run_cli(const std::string& arguments) {
  const std::string command = std::string(CLEARSKY_BINARY_DIR) + "/clearsky " + arguments;
  std::string output;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return output;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) output += buffer.data();
  EXPECT_EQ(::pclose(pipe), 0) << command;
  return output;
}

std::filesystem::path archive(const std::string& time) {
  return clearsky::testing::shared_data_dir() / "kider2014/2013-05-27/RADIANCE" /
         ("2013-05-27___" + time + ".00.7z");
}

std::string bytes_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

TEST(CliApiParity, PreethamOnTwoCapturesGivesTheSameRmseBothWays) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  clearsky::testing::TempDir dir;
  const std::string cli_db = (dir.path / "cli.db").string();
  const nlohmann::json cli_import = nlohmann::json::parse(
      run_cli("import kider " + archive("10.00").string() + " " + archive("12.00").string() +
              " --name pair --db " + cli_db + " --json"));
  const nlohmann::json cli = nlohmann::json::parse(
      run_cli("evaluate --dataset pair --models preetham --json --samples=spectra --db " + cli_db));

  const auto api_db = dir.path / "api.db";
  storage::Database db = storage::open_database(api_db);
  std::vector<std::string> api_added;
  std::int64_t api_samples = 0;
  {
    api::ImportPool imports([api_db] { return storage::open_database(api_db); });
    std::vector<std::int64_t> ids;
    for (const char* time : {"10.00", "12.00"}) {
      auto spool = std::make_unique<api::UploadSpool>(dir.path / "uploads", 8u << 20, ".7z");
      spool->append(bytes_of(archive(time)));
      const std::filesystem::path source = spool->finish();
      storage::NewImport what;
      what.dataset = "pair";
      what.format = "kider";
      what.source = "upload";
      what.upload_bytes = static_cast<std::int64_t>(spool->size_bytes());
      ids.push_back(imports.submit(db, what, source, std::move(spool)));
    }
    imports.wait_idle();
    for (const std::int64_t id : ids) {
      const auto shown = api::show_import(db, &imports, id);
      ASSERT_EQ(shown["status"], "succeeded") << shown.dump();
      for (const auto& label : shown["report"]["added"]) api_added.push_back(label);
      api_samples += shown["report"]["samples_added"].get<std::int64_t>();
    }
  }
  EXPECT_EQ(cli_import["added"].get<std::vector<std::string>>(), api_added);
  EXPECT_EQ(cli_import["samples_added"].get<std::int64_t>(), api_samples);
  api::EvaluationPool pool([api_db] { return storage::open_database(api_db); },
                           registered_models());
  const std::int64_t ticket = pool.submit(api::parse_evaluation_request(
      db, R"({"models": ["preetham"], "dataset": "pair"})", registered_models(), "test"));
  pool.wait_idle();
  ASSERT_EQ(pool.ticket(ticket)->status, "succeeded") << pool.ticket(ticket)->error;
  const auto run = api::show_evaluation(db, pool.ticket(ticket)->run_ids.at(0),
                                        {api::SampleDetail::spectra, std::nullopt});

  const auto& model = cli["models"][0];
  EXPECT_EQ(model["model"], "preetham");
  EXPECT_DOUBLE_EQ(run["rmse"].get<double>(), model["rmse"].get<double>());
  ASSERT_EQ(run["captures"].size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(run["captures"][i]["time"].dump(), model["captures"][i]["time"].dump());
    EXPECT_DOUBLE_EQ(run["captures"][i]["rmse"].get<double>(),
                     model["captures"][i]["rmse"].get<double>());
    EXPECT_DOUBLE_EQ(run["captures"][i]["sun_azimuth"].get<double>(),
                     model["captures"][i]["sun_azimuth"].get<double>());
    // The same numbers, sample by sample and wavelength by wavelength.
    ASSERT_EQ(run["captures"][i]["samples"].size(), 81u);
    EXPECT_EQ(nlohmann::json(run["captures"][i]["samples"]), model["captures"][i]["samples"]);
  }
  EXPECT_EQ(nlohmann::json(run["wavelengths_nm"]), model["wavelengths_nm"]);
  EXPECT_EQ(run["wavelengths_nm"].size(), 31u);
  // A real RMSE of a real model, not a degenerate zero.
  EXPECT_GT(run["rmse"].get<double>(), 1.0);
}

}  // namespace
}  // namespace clearsky
