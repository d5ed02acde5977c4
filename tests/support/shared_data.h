// Where tests find the measurement data (the Kider 2014 captures; README.md "Data"). Absent data
// skips a test with a message, except under CI=true, where it is a failure (CONTRIBUTING.md "Build
// and test").
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace clearsky::testing {

inline std::filesystem::path shared_data_dir() { return CLEARSKY_SHARED_DATA_DIR; }

inline bool running_in_ci() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::string(ci) == "true";
}

}  // namespace clearsky::testing

// Skips (or, in CI, fails) the current test when the shared measurement data is missing.
#define CLEARSKY_REQUIRE_SHARED_DATA(relative)                                       \
  do {                                                                               \
    const auto clearsky_path_ = ::clearsky::testing::shared_data_dir() / (relative); \
    if (!std::filesystem::exists(clearsky_path_)) {                                  \
      if (::clearsky::testing::running_in_ci()) {                                    \
        FAIL() << "CI=true and the shared data is missing: " << clearsky_path_;      \
      }                                                                              \
      GTEST_SKIP() << "shared data not found at " << clearsky_path_;                 \
    }                                                                                \
  } while (false)
