// `clearsky sun` end to end: runs the built executable and checks its output and exit status.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/place_time_cases.h"

namespace {

struct CommandRun {
  std::string output;  // stdout and stderr
  int exit_status = -1;
};

CommandRun run_clearsky(const std::string& arguments) {
  const std::string command = std::string(CLEARSKY_BINARY_DIR) + "/clearsky " + arguments + " 2>&1";
  CommandRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return run;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) run.output.append(buffer, n);
  const int status = pclose(pipe);
  run.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

constexpr const char* kReportExample =
    "sun --lat 39.742476 --lon -105.1786 --elevation 1830.14 --time 2003-10-17T12:30:30-07:00 "
    "--pressure 820 --temperature 11 --delta-t 67";

TEST(SunCommand, ReportExampleAsJson) {
  const CommandRun run = run_clearsky(std::string(kReportExample) + " --json");
  ASSERT_EQ(run.exit_status, 0) << run.output;
  const nlohmann::json answer = nlohmann::json::parse(run.output);
  EXPECT_NEAR(answer.at("zenith").get<double>(), 50.11162, 1e-5);
  EXPECT_NEAR(answer.at("azimuth").get<double>(), 194.34024, 1e-5);
  EXPECT_EQ(answer.at("sunrise"), "2003-10-17T06:12:43-07:00");
  EXPECT_EQ(answer.at("transit"), "2003-10-17T11:46:05-07:00");
  EXPECT_EQ(answer.at("sunset").get<std::string>().substr(0, 17), "2003-10-17T17:18:");
}

TEST(SunCommand, TextFormAndNoRefraction) {
  const CommandRun text = run_clearsky(kReportExample);
  ASSERT_EQ(text.exit_status, 0) << text.output;
  EXPECT_NE(text.output.find("zenith   50.111622 degrees"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("sunrise  2003-10-17T06:12:43-07:00"), std::string::npos)
      << text.output;

  const CommandRun raw = run_clearsky(std::string(kReportExample) + " --no-refraction --json");
  ASSERT_EQ(raw.exit_status, 0) << raw.output;
  // SPA's refraction at this elevation, pressure and temperature is 0.016332 degrees.
  EXPECT_NEAR(nlohmann::json::parse(raw.output).at("zenith").get<double>(), 50.11162 + 0.016332,
              2e-5);
}

TEST(SunCommand, DmsInputAtTheKiderSite) {
  const CommandRun run = run_clearsky(
      "sun --lat \"42d26'36.4\\\"N\" --lon \"76d28'55.1\\\"W\" "
      "--time 2013-05-27T11:45:00-04:00 --no-refraction --json");
  ASSERT_EQ(run.exit_status, 0) << run.output;
  const nlohmann::json answer = nlohmann::json::parse(run.output);
  EXPECT_NEAR(answer.at("zenith").get<double>(), 26.654, 0.005);
  EXPECT_NEAR(answer.at("azimuth").get<double>(), 136.065, 0.015);
}

TEST(SunCommand, PolarDayHasNullSunriseAndSunset) {
  const CommandRun run =
      run_clearsky("sun --lat 80 --lon 15 --time 2023-06-21T12:00:00+02:00 --json");
  ASSERT_EQ(run.exit_status, 0) << run.output;
  const nlohmann::json answer = nlohmann::json::parse(run.output);
  EXPECT_TRUE(answer.at("sunrise").is_null());
  EXPECT_TRUE(answer.at("sunset").is_null());
  EXPECT_EQ(answer.at("day"), "polar_day");
  EXPECT_EQ(answer.at("transit").get<std::string>().substr(0, 11), "2023-06-21T");
}

TEST(SunCommand, InvalidInputNamesTheOptionAndFails) {
  struct Case {
    const char* arguments;
    const char* option;
  };
  for (const Case& c :
       {Case{"sun --lat nan --lon 0", "--lat"}, Case{"sun --lat 91 --lon 0", "--lat"},
        Case{"sun --lat 0 --lon 181", "--lon"}, Case{"sun --lon 0", "--lat"},
        Case{"sun --lat 0 --lon 0 --time 2013-05-27T11:45:00", "--time"},
        Case{"sun --lat 0 --lon 0 --pressure nan", "--pressure"},
        Case{"sun --lat 0 --lon 0 --elevation -7e6", "--elevation"},
        Case{"sun --lat 0 --lon 0 --delta-t 1e4", "--delta-t"},
        Case{"sun --lat 0 --lon 0 --time 7000-01-01T00:00:00Z", "--time"},
        Case{"sun --lat 0 --lon 0 --delta-ut1 1", "--delta-ut1"},
        Case{"sun --lat 0 --lon 0 --altitude 2e7", "--elevation"}}) {
    const CommandRun run = run_clearsky(c.arguments);
    EXPECT_NE(run.exit_status, 0) << c.arguments;
    EXPECT_NE(run.output.find(std::string("clearsky: ") + c.option + ":"), std::string::npos)
        << c.arguments << " -> " << run.output;
  }
}

// The options take the values GET /v1/sun and the sky endpoints take (one table,
// api/request/place_time.h), and refuse the others naming the option.
TEST(SunCommand, SameRangesAsTheApi) {
  for (const auto& c : clearsky::testing::place_time_cases()) {
    if (c.parameter == "refraction") continue;  // a flag here (--no-refraction)
    std::string option = "--" + c.parameter;
    std::replace(option.begin(), option.end(), '_', '-');
    std::string arguments = "sun";
    for (const char* name : {"lat", "lon", "time"}) {
      if (c.parameter != name)
        arguments += std::string(" --") + name + " " +
                     (std::string(name) == "time" ? "2013-05-27T11:45:00-04:00" : "10");
    }
    // delta_t given: the years after 3000 have no computed default (models/solar/delta_t.h).
    if (c.parameter != "delta_t") arguments += " --delta-t 69";
    arguments += " " + option + " " + c.value + " --json";
    const CommandRun run = run_clearsky(arguments);
    if (c.accepted) {
      EXPECT_EQ(run.exit_status, 0) << arguments << " -> " << run.output;
    } else {
      EXPECT_NE(run.exit_status, 0) << arguments;
      // altitude's first option name is --elevation.
      const std::string shown = c.parameter == "altitude" ? "--elevation" : option;
      EXPECT_NE(run.output.find("clearsky: " + shown + ":"), std::string::npos)
          << arguments << " -> " << run.output;
    }
  }
}

}  // namespace
