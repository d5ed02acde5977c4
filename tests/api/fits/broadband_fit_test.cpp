// The atmosphere fit to a broadband irradiance series (api/fits/broadband_fit.h): a day of GHI
// that Bruneton's model made with a known Angstrom beta (small tables, so that every point is
// quick) is fitted back to that beta, with the RMSE at the start above the RMSE after; a model
// without a broadband answer is refused naming model.
#include "api/fits/broadband_fit.h"

#include <gtest/gtest.h>

#include "api/evaluation/broadband_evaluation.h"
#include "models/core/invalid_input.h"
#include "models/registry.h"
#include "tests/support/rhodes_irradiance_instants.h"

namespace clearsky::api {
namespace {

constexpr double kMadeBeta = 0.1;

// 2013-05-27 at Rhodes Hall, 08:00 to 18:00 EDT every hour.
std::vector<storage::IrradianceSample> rhodes_day() {
  std::vector<storage::IrradianceSample> samples;
  for (int hour = 8; hour <= 18; ++hour)  // from 08:00 EDT
    samples.push_back(clearsky::testing::rhodes_hall_sample(1369656000.0 + (hour - 8) * 3600.0));
  return samples;
}

// Tiny tables on ten 47-nm bins over the paper's range, two orders: each point of the fit builds
// its tables in a fraction of a second, also under the sanitizers (the fit's own cheap search
// setting on 40 bins took 47 s here on a loaded machine). The made day and the fit share them,
// so the fit must find the made beta exactly whatever their accuracy.
ModelConfig small_tables(const ModelDescriptor&) {
  ModelConfig config;
  config.wavelengths = WavelengthGrid::bins(360.0, 47.0, 10);
  config.options = {{"table_r_size", 3},
                    {"table_mu_size", 8},
                    {"table_mu_s_size", 4},
                    {"table_nu_size", 2},
                    {"scattering_orders", 2}};
  return config;
}

TEST(BroadbandFit, RecoversTheBetaThatMadeADayOfGhi) {
  const ModelFactory& bruneton = *find_model("bruneton");
  ModelConfig made = small_tables(*bruneton.descriptor);
  const std::vector<FreeParameter> free =
      make_free_parameters(*bruneton.descriptor, std::vector<std::string>{"beta"},
                           FitBounds{{"beta", {0.02, 0.3}}}, std::vector<int>{5});
  made = with_values(made, free, std::vector<double>{kMadeBeta});
  std::vector<storage::IrradianceSample> samples = rhodes_day();
  const auto model = bruneton.create(made, {});
  const auto modelled = modelled_broadband_irradiance(*model, samples);
  for (std::size_t i = 0; i < samples.size(); ++i) samples[i].ghi_w_m2 = *modelled[i].ghi_w_m2;

  FitSettings settings;
  settings.parameters = free;
  settings.config = small_tables(*bruneton.descriptor);  // beta at its default, 0.04
  settings.relative_tolerance = 5e-3;                    // of the bounds' width: 0.0014 in beta
  const FitResult fit = fit_broadband(bruneton, samples, settings);
  ASSERT_EQ(fit.values.size(), 1u);
  EXPECT_NEAR(fit.values[0], kMadeBeta, 0.003);
  EXPECT_NEAR(fit.initial_values[0], 0.04, 1e-12);
  EXPECT_GT(fit.rmse_before, 10.0);
  EXPECT_LT(fit.rmse_after, 1.0);
  EXPECT_EQ(fit.rmse_after, fit.rmse_search);  // search and confirmation at the same setting
  EXPECT_GE(fit.uncertainty[0].sampled_high, fit.values[0]);
}

TEST(BroadbandFit, AModelWithoutABroadbandAnswerIsRefusedNamingModel) {
  const ModelFactory& preetham = *find_model("preetham");
  FitSettings settings;
  settings.parameters =
      make_free_parameters(*preetham.descriptor, std::vector<std::string>{"turbidity"});
  try {
    fit_broadband(preetham, rhodes_day(), settings);
    FAIL() << "no refusal";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "model");
  }
}

}  // namespace
}  // namespace clearsky::api
