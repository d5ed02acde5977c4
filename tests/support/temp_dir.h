// The temporary folder (and database) of a test: a fresh folder named after the process and
// the running test, created empty and removed with its content when the fixture goes out of
// scope. database_path() names a SQLite file inside it (storage::open_database or the CLI's
// --db create it on first use).
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <string>

namespace clearsky::testing {

class TempDir {
 public:
  TempDir() {
    static std::atomic<int> count{0};
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string test =
        info != nullptr ? std::string(info->test_suite_name()) + "_" + info->name() : "no_test";
    path = std::filesystem::temp_directory_path() /
           ("clearsky_" + std::to_string(::getpid()) + "_" + test + "_" + std::to_string(++count));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::filesystem::path database_path(const std::string& name = "sky.db") const {
    return path / name;
  }

  std::filesystem::path path;
};

}  // namespace clearsky::testing
