// The C++ client's reading of evaluation runs (clients/cpp/src/data_json.h) on the answers the
// server gives (docs/data-api.md "Evaluations of broadband irradiance"): a run on a broadband
// irradiance dataset has its RMSE in W/m2 (rmse_w_m2, not rmse_mw_m2_sr_nm) and each
// component's RMSE, bias, count and per-sample errors; a run on captures keeps its RMSE in
// mW/(m2.sr.nm) and no components.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "clients/cpp/src/data_json.h"

namespace clearsky::client {
namespace {

const nlohmann::json kComponents = nlohmann::json::parse(R"([
  {"component": "ghi", "rmse_w_m2": 37.3, "mean_bias_w_m2": -34.2, "samples_compared": 2,
   "errors_w_m2": [null, -30.1, -38.3]},
  {"component": "dni", "rmse_w_m2": null, "mean_bias_w_m2": null, "samples_compared": 0}])");

TEST(EvaluationJson, ABroadbandRunHasItsRmseInWattsPerM2AndEachComponent) {
  nlohmann::json j = {{"id", 4},
                      {"dataset", "roof"},
                      {"model", "nishita93"},
                      {"model_version", "1"},
                      {"parameters", nlohmann::json::object()},
                      {"software_version", "test"},
                      {"wavelength_range_nm", {300.0, 4000.0}},
                      {"job", nullptr},
                      {"status", "succeeded"},
                      {"error", nullptr},
                      {"started", "2026-11-27T20:00:00.000Z"},
                      {"finished", "2026-11-27T20:00:01.000Z"},
                      {"rmse", 37.3},
                      {"rmse_unit", "W/m2"},
                      {"irradiance_components", kComponents},
                      {"out_of_domain", "exclude"},
                      {"samples_compared", nullptr},
                      {"processing_steps", nlohmann::json::array()},
                      {"captures", nlohmann::json::array()}};
  const Evaluation run = detail::evaluation_of(j);
  EXPECT_EQ(run.rmse_w_m2, 37.3);
  EXPECT_FALSE(run.rmse_mw_m2_sr_nm);
  ASSERT_EQ(run.irradiance_components.size(), 2u);
  EXPECT_EQ(run.irradiance_components[0].component, "ghi");
  EXPECT_EQ(run.irradiance_components[0].mean_bias_w_m2, -34.2);
  EXPECT_EQ(run.irradiance_components[0].samples_compared, 2);
  ASSERT_EQ(run.irradiance_components[0].errors_w_m2.size(), 3u);
  EXPECT_FALSE(run.irradiance_components[0].errors_w_m2[0]);
  EXPECT_EQ(run.irradiance_components[0].errors_w_m2[2], -38.3);
  EXPECT_FALSE(run.irradiance_components[1].rmse_w_m2);
  EXPECT_TRUE(run.irradiance_components[1].errors_w_m2.empty());

  const EvaluationSummary summary =
      detail::evaluation_summary_of({{"id", 4},
                                     {"dataset", "roof"},
                                     {"model", "nishita93"},
                                     {"status", "succeeded"},
                                     {"started", "2026-11-27T20:00:00.000Z"},
                                     {"finished", nullptr},
                                     {"rmse", 37.3},
                                     {"rmse_unit", "W/m2"},
                                     {"samples_compared", 2},
                                     {"irradiance_components", kComponents},
                                     {"job", nullptr}});
  EXPECT_EQ(summary.rmse_w_m2, 37.3);
  EXPECT_EQ(summary.irradiance_components.size(), 2u);
}

TEST(EvaluationJson, ARunOnCapturesKeepsItsSpectralRmse) {
  const EvaluationSummary summary =
      detail::evaluation_summary_of({{"id", 1},
                                     {"dataset", "kider"},
                                     {"model", "preetham"},
                                     {"status", "succeeded"},
                                     {"started", "2026-11-27T20:00:00.000Z"},
                                     {"finished", nullptr},
                                     {"rmse", 88.7},
                                     {"rmse_unit", "mW/(m2.sr.nm)"},
                                     {"samples_compared", 81},
                                     {"irradiance_components", nlohmann::json::array()},
                                     {"job", nullptr}});
  EXPECT_EQ(summary.rmse_mw_m2_sr_nm, 88.7);
  EXPECT_FALSE(summary.rmse_w_m2);
  EXPECT_TRUE(summary.irradiance_components.empty());
}

}  // namespace
}  // namespace clearsky::client
