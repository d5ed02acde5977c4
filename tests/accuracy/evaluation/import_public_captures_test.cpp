// The import's acceptance check: `clearsky import kider` of the 15 public archives gives 15
// captures x 81 samples, and a second import changes nothing. Runs the executable.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

namespace clearsky {
namespace {

std::pair<int, std::string> run(const std::string& arguments) {
  const std::string command = std::string(CLEARSKY_BINARY_DIR) + "/clearsky " + arguments + " 2>&1";
  std::string output;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return {-1, ""};
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) output += buffer.data();
  const int status = ::pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

TEST(ImportPublicCaptures, FifteenCapturesOf81Samples) {
  const auto folder = testing::shared_data_dir() / "kider2014/2013-05-27/RADIANCE";
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  const testing::TempDir dir;
  const std::string db = dir.database_path().string();
  const std::string archives = folder.string() + "/*.7z";

  const auto start = std::chrono::steady_clock::now();
  const auto [code, output] = run("import kider " + archives + " --db " + db + " --json");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(code, 0) << output;
  EXPECT_EQ(nlohmann::json::parse(output).at("added").size(), 15u);
  std::printf("clearsky import kider of the 15 archives: %.2f s\n", seconds);

  const auto listed = run("datasets --json --db " + db);
  EXPECT_EQ(nlohmann::json::parse(listed.second),
            nlohmann::json::parse(R"([{"name": "kider2014", "captures": 15, "samples": 1215}])"));
  const auto again = run("import kider " + archives + " --db " + db + " --json");
  ASSERT_EQ(again.first, 0) << again.second;
  EXPECT_EQ(nlohmann::json::parse(again.second).at("unchanged").size(), 15u);
  EXPECT_EQ(nlohmann::json::parse(again.second).at("added").size(), 0u);
}

}  // namespace
}  // namespace clearsky
