// Fits recover the parameters that made synthetic measurements (models/fitting/atmosphere_fit.h,
// docs/fits.md "Tests"): Preetham's turbidity, Hosek's turbidity and ground albedo, and the
// Bruneton family's beta on the cheapest tables.
#include "models/fitting/atmosphere_fit.h"

#include <gtest/gtest.h>

#include <cmath>

#include "models/core/invalid_input.h"
#include "models/registry.h"
#include "tests/models/fitting/model_made_sky.h"

namespace clearsky {
namespace {

const ModelFactory& factory_of(const char* id) {
  const ModelFactory* factory = find_model(id);
  if (factory == nullptr) throw std::logic_error(std::string("no model ") + id);
  return *factory;
}

std::vector<MeasuredCapture> made_by(const ModelFactory& factory, const ModelConfig& config) {
  const std::shared_ptr<const SkyModel> model = factory.create(config, {});
  return {testing::model_made_capture(*model, 30.0, 120.0),
          testing::model_made_capture(*model, 45.0, 100.0),
          testing::model_made_capture(*model, 22.0, 170.0)};
}

TEST(AtmosphereFit, RecoversPreethamTurbidity) {
  const ModelFactory& preetham = factory_of("preetham");
  ModelConfig truth;
  truth.wavelengths = testing::integer_nm_grid(10);
  truth.atmosphere.turbidity = 3.4;
  const std::vector<MeasuredCapture> captures = made_by(preetham, truth);
  FitSettings settings;
  settings.config.wavelengths = truth.wavelengths;
  const std::vector<std::string> free = {"turbidity"};
  settings.parameters = make_free_parameters(*preetham.descriptor, free);
  settings.cross_validate = true;
  settings.per_capture = true;
  const FitResult fit = fit_model(preetham, captures, settings);
  ASSERT_EQ(fit.values.size(), 1u);
  EXPECT_NEAR(fit.values[0], 3.4, 1e-3);
  EXPECT_GT(fit.rmse_before, 1.0);  // the default turbidity, 2.53, is far from 3.4
  EXPECT_LT(fit.rmse_after, 1e-3 * fit.rmse_before);
  EXPECT_LE(fit.rmse_after, fit.grid_rmse);
  EXPECT_EQ(fit.grid_evaluations, 21u);  // turbidity alone: 21 points over [2, 10]
  EXPECT_FALSE(fit.search_setting_differs);
  // Exact data: the 1% band is narrow and holds the truth.
  ASSERT_EQ(fit.uncertainty.size(), 1u);
  EXPECT_LE(fit.uncertainty[0].scan_low, 3.4);
  EXPECT_GE(fit.uncertainty[0].scan_high, 3.4);
  EXPECT_LT(fit.uncertainty[0].scan_high - fit.uncertainty[0].scan_low, 0.5);
  EXPECT_LE(fit.uncertainty[0].sampled_low, fit.uncertainty[0].scan_low + 1e-9);
  // Every capture alone and every fold recover it too; held-out RMSE is then ~0.
  ASSERT_TRUE(fit.cross_validated_rmse.has_value());
  EXPECT_LT(*fit.cross_validated_rmse, 1e-2);
  for (const CaptureFit& c : fit.captures) {
    ASSERT_EQ(c.own_values.size(), 1u);
    EXPECT_NEAR(c.own_values[0], 3.4, 1e-2) << c.label;
    EXPECT_NEAR(c.fold_values[0], 3.4, 1e-2) << c.label;
  }
  std::size_t grid_samples = 0;
  for (const FitSample& s : fit.history) grid_samples += s.stage == "grid" ? 1 : 0;
  EXPECT_EQ(grid_samples, 21u);
  EXPECT_EQ(fit.history.front().stage, "grid");
}

TEST(AtmosphereFit, RecoversHosekTurbidityAndAlbedo) {
  const ModelFactory& hosek = factory_of("hosek");
  ModelConfig truth;
  truth.wavelengths = testing::integer_nm_grid(10);
  truth.atmosphere.turbidity = 4.2;
  truth.atmosphere.ground_albedo = 0.3;
  const std::vector<MeasuredCapture> captures = made_by(hosek, truth);
  FitSettings settings;
  settings.config.wavelengths = truth.wavelengths;
  settings.config.atmosphere.ground_albedo = 0.1;
  const std::vector<std::string> free = {"turbidity", "albedo"};
  settings.parameters = make_free_parameters(*hosek.descriptor, free);
  const FitResult fit = fit_model(hosek, captures, settings);
  ASSERT_EQ(fit.values.size(), 2u);
  EXPECT_EQ(fit.grid_evaluations, 11u * 11u);
  EXPECT_EQ(fit.refine_algorithm, "LN_BOBYQA");
  EXPECT_NEAR(fit.values[0], 4.2, 1e-2);
  EXPECT_NEAR(fit.values[1], 0.3, 1e-2);
  EXPECT_LT(fit.rmse_after, 1e-2 * fit.rmse_before);
}

// Tables far below the cheap search setting and few wavelengths, so that each build takes
// milliseconds: the data and the fit use the same ones, so the truth is exactly recoverable.
ModelConfig tiny_bruneton() {
  ModelConfig config;
  config.wavelengths = testing::integer_nm_grid(40);
  config.options = {{"table_r_size", 3},
                    {"table_mu_size", 8},
                    {"table_mu_s_size", 4},
                    {"table_nu_size", 2},
                    {"scattering_orders", 2}};
  return config;
}

TEST(AtmosphereFit, RecoversBrunetonBeta) {
  const ModelFactory& bruneton = factory_of("bruneton");
  ModelConfig truth = tiny_bruneton();
  truth.atmosphere.angstrom_beta = 0.11;
  const std::vector<MeasuredCapture> captures = made_by(bruneton, truth);
  FitSettings settings;
  settings.config = tiny_bruneton();
  const std::vector<std::string> free = {"beta"};
  const std::vector<int> grid = {5};
  settings.parameters = make_free_parameters(*bruneton.descriptor, free, {}, grid);
  settings.max_refine_evaluations = 12;
  settings.scan_bisections = 1;
  const FitResult fit = fit_model(bruneton, captures, settings);
  EXPECT_NEAR(fit.values[0], 0.11, 2e-3);
  EXPECT_EQ(fit.grid_evaluations, 5u);
  EXPECT_LT(fit.rmse_after, 0.05 * fit.rmse_before);
}

// The search runs on other tables (and only the compared wavelengths); the RMSE it reports is
// the one of those tables on the full grid (each wavelength is computed on its own), and the
// RMSE after is the standard setting's at the values found.
TEST(AtmosphereFit, SearchesOnOtherTablesAndConfirmsAtTheStandardSetting) {
  const ModelFactory& bruneton = factory_of("bruneton");
  ModelConfig standard = tiny_bruneton();
  standard.wavelengths = WavelengthGrid::bins(320.0, 40.0, 11);  // 320 .. 720: 10 compared
  const std::vector<MeasuredCapture> captures = {
      testing::synthetic_capture([](const ViewDirection&, double) { return 0.01; })};
  FitSettings settings;
  settings.config = standard;
  settings.search_options = {{"table_r_size", 4}};
  const std::vector<std::string> free = {"beta"};
  const std::vector<int> grid = {2};
  settings.parameters = make_free_parameters(*bruneton.descriptor, free, {}, grid);
  settings.max_refine_evaluations = 0;
  settings.scan_bisections = 0;
  const FitResult fit = fit_model(bruneton, captures, settings);
  EXPECT_TRUE(fit.search_setting_differs);
  ModelConfig search = with_values(standard, fit.parameters, fit.values);
  search.options["table_r_size"] = 4;
  EXPECT_NEAR(fit.rmse_search, evaluate_model(bruneton, search, captures).rmse,
              1e-9 * fit.rmse_search);
  EXPECT_EQ(
      fit.rmse_after,
      evaluate_model(bruneton, with_values(standard, fit.parameters, fit.values), captures).rmse);
  EXPECT_NE(fit.rmse_after, fit.rmse_search);
}

TEST(FitSpace, StudyGridForTheBrunetonFamily) {
  const ModelFactory& bruneton = factory_of("bruneton");
  const std::vector<std::string> free = default_free_parameters(*bruneton.descriptor);
  ASSERT_EQ(free, (std::vector<std::string>{"alpha", "beta", "g"}));
  const std::vector<FreeParameter> parameters = make_free_parameters(*bruneton.descriptor, free);
  EXPECT_EQ(grid_points(parameters).size(), 11u * 10u * 5u);
  EXPECT_EQ(grid_values(parameters[1]).front(), 0.02);
  EXPECT_EQ(grid_values(parameters[1]).back(), 0.2);
  EXPECT_NEAR(grid_values(parameters[0])[1], 0.2, 1e-12);
  EXPECT_EQ(cheap_search_options(*bruneton.descriptor).size(), 4u);
  EXPECT_TRUE(cheap_search_options(*factory_of("preetham").descriptor).empty());
}

TEST(FitSpace, RefusesWhatCannotBeFitted) {
  const ModelDescriptor& bruneton = *factory_of("bruneton").descriptor;
  const auto refused = [&](std::vector<std::string> free, FitBounds bounds,
                           std::vector<int> grid) -> std::string {
    try {
      make_free_parameters(bruneton, free, bounds, grid);
    } catch (const InvalidInput& e) {
      return e.field();
    }
    return "";
  };
  EXPECT_EQ(refused({"turbidity"}, {}, {}), "free");          // not a Bruneton parameter
  EXPECT_EQ(refused({"scattering_orders"}, {}, {}), "free");  // an integer option
  EXPECT_EQ(refused({"beta", "beta"}, {}, {}), "free");
  EXPECT_EQ(refused({}, {}, {}), "free");
  EXPECT_EQ(refused({"beta"}, {{"alpha", {0, 1}}}, {}), "bounds");
  EXPECT_EQ(refused({"beta"}, {{"beta", {0.2, 0.1}}}, {}), "bounds");
  EXPECT_EQ(refused({"beta"}, {{"beta", {0.1, 0.1}}}, {}), "bounds");
  EXPECT_EQ(refused({"beta"}, {{"beta", {0.1, 5}}}, {}), "bounds");
  EXPECT_EQ(refused({"beta"}, {{"beta", {std::nan(""), 0.1}}}, {}), "bounds");
  EXPECT_EQ(refused({"beta"}, {}, {0}), "grid");
  EXPECT_EQ(refused({"beta"}, {}, {3, 4}), "grid");
  EXPECT_EQ(refused({"beta"}, {{"beta", {0.05, 0.1}}}, {3}), "");
}

}  // namespace
}  // namespace clearsky
