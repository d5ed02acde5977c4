// End-to-end tests of `clearsky fit` (server/cli/fit_command.cpp, docs/fits.md), run as a user
// would on a temporary database: Preetham's turbidity fitted to two public captures, stored and
// printed as JSON with its error bars, and requests refused before anything is computed.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

namespace clearsky {
namespace {

struct Result {
  int exit_code = -1;
  std::string output;  // stdout (stderr with merged)
};

Result run(const std::string& arguments, bool merged = true) {
  const std::string command = std::string(CLEARSKY_BINARY_DIR) + "/clearsky " + arguments +
                              (merged ? " 2>&1" : " 2>/dev/null");
  Result result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) result.output += buffer.data();
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string archive(const std::string& time) {
  return (clearsky::testing::shared_data_dir() / "kider2014/2013-05-27/RADIANCE" /
          ("2013-05-27___" + time + ".00.7z"))
      .string();
}

TEST(FitCommand, FitsPreethamTurbidityWithErrorBars) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  clearsky::testing::TempDir temp;
  const std::string db = (temp.path / "sky.db").string();
  ASSERT_EQ(
      run("import kider " + archive("09.30") + " " + archive("12.30") + " --name day --db " + db)
          .exit_code,
      0);
  const Result fitted = run(
      "fit --dataset day --model preetham --cross-validate --per-capture --history --json --db " +
          db,
      false);
  ASSERT_EQ(fitted.exit_code, 0) << fitted.output;
  const auto fit = nlohmann::json::parse(fitted.output);
  EXPECT_EQ(fit.at("status"), "succeeded");
  EXPECT_EQ(fit.at("model"), "preetham");
  EXPECT_EQ(fit.at("free_parameters").at(0).at("name"), "turbidity");
  EXPECT_EQ(fit.at("search").at("grid").at("evaluations"), 21);
  const double turbidity = fit.at("values").at("turbidity").get<double>();
  EXPECT_GE(turbidity, 2.0);
  EXPECT_LE(turbidity, 10.0);
  // The default turbidity (2.53) is one of the points the fit could have kept: it cannot end
  // worse (study: 88.72 over the 15 captures).
  EXPECT_LE(fit.at("rmse_after").get<double>(), fit.at("rmse_before").get<double>() + 1e-9);
  EXPECT_GT(fit.at("cross_validated_rmse").get<double>(), 0.0);
  const auto& u = fit.at("uncertainty").at(0);
  EXPECT_LE(u.at("scan").at(0).get<double>(), turbidity);
  EXPECT_GE(u.at("scan").at(1).get<double>(), turbidity);
  ASSERT_EQ(fit.at("captures_fitted").size(), 2u);
  EXPECT_TRUE(fit.at("captures_fitted").at(1).contains("own_values"));
  EXPECT_TRUE(fit.at("captures_fitted").at(1).contains("held_out_rmse"));
  EXPECT_GT(fit.at("history").size(), 21u);

  // Stored: a second fit gets the next id; --captures restricts the fit to the labels given.
  const Result one =
      run("fit --dataset day --model preetham --captures 2013-05-27___12.30.00 --json --db " + db,
          false);
  ASSERT_EQ(one.exit_code, 0) << one.output;
  const auto second = nlohmann::json::parse(one.output);
  EXPECT_EQ(second.at("id").get<int>(), fit.at("id").get<int>() + 1);
  EXPECT_EQ(second.at("captures_fitted").size(), 1u);
}

TEST(FitCommand, RefusesWhatCannotBeFitted) {
  clearsky::testing::TempDir temp;
  const std::string db = (temp.path / "sky.db").string();
  const Result unknown_model = run("fit --dataset day --model nishita2042 --db " + db);
  EXPECT_NE(unknown_model.exit_code, 0);
  EXPECT_NE(unknown_model.output.find("nishita2042"), std::string::npos) << unknown_model.output;
  const Result integer =
      run("fit --dataset day --model bruneton --free scattering_orders --db " + db);
  EXPECT_NE(integer.exit_code, 0);
  EXPECT_NE(integer.output.find("integer option"), std::string::npos) << integer.output;
  const Result bounds =
      run("fit --dataset day --model preetham --bounds '{\"turbidity\": [1, 3]}' --db " + db);
  EXPECT_NE(bounds.exit_code, 0);
  EXPECT_NE(bounds.output.find("inside [2, 10]"), std::string::npos) << bounds.output;
  const Result no_dataset = run("fit --dataset missing --model preetham --db " + db);
  EXPECT_EQ(no_dataset.exit_code, 1);
  EXPECT_NE(no_dataset.output.find("no dataset named 'missing'"), std::string::npos)
      << no_dataset.output;
}

}  // namespace
}  // namespace clearsky
