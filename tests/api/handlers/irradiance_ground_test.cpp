// The ground-reflected irradiance of GET /v1/irradiance (api/irradiance/plane_irradiance.h) on
// the analytic test sky, whose direct and sky irradiance are closed forms
// (tests/support/test_sky_model.h): albedo x global horizontal x (1 - cos tilt) / 2.
#include <gtest/gtest.h>

#include <cmath>

#include "api/handlers/handlers.h"
#include "models/core/numeric.h"
#include "tests/support/synchronous_provider.h"
#include "tests/support/test_sky_model.h"

namespace clearsky::api {
namespace {

using Q = std::vector<std::pair<std::string, std::string>>;

class IrradianceGround : public ::testing::Test {
 protected:
  ApiResponse call(Q extra) {
    Q q{{"model", "testsky"}, {"sun_zenith", "30"}, {"sun_azimuth", "120"}, {"spectral", "true"}};
    q.insert(q.end(), extra.begin(), extra.end());
    ApiRequest r{"GET", "/v1/irradiance", std::move(q), ""};
    const ApiContext context{provider, limits};
    try {
      return irradiance(context, r);
    } catch (const ApiError& e) {
      return error_response(e);
    }
  }
  // The test sky's global horizontal at wavelength lambda: DNI cos 30 + the sky's pi + 2 pi / 3.
  static double ghi(double lambda_nm) {
    return 1.5 * lambda_nm / 500.0 * std::cos(degrees_to_radians(30.0)) +
           0.01 * lambda_nm / 500.0 * 5.0 * kPi / 3.0;
  }

  clearsky::testing::SynchronousProvider provider{clearsky::testing::test_factories()};
  Limits limits{100, 500, 1024};
};

TEST_F(IrradianceGround, VerticalPlaneGetsHalfTheAlbedoTimesGlobalHorizontal) {
  const ApiResponse r =
      call({{"tilt", "90"}, {"surface_azimuth", "300"}, {"ground_albedo", "0.3"}});
  ASSERT_EQ(r.status, 200) << r.body;
  const auto j = nlohmann::json::parse(r.body);
  const auto grid = WavelengthGrid::paper_bins();
  for (std::size_t i = 0; i < grid.size(); ++i) {
    EXPECT_NEAR(j["ground_diffuse"]["spectral_w_m2_nm"][i].get<double>(), 0.3 * ghi(grid[i]) / 2,
                1e-12);
  }
  // Facing away from the sun: global is the sky's and the ground's light only.
  EXPECT_NEAR(j["global"]["irradiance_w_m2"].get<double>(),
              j["diffuse"]["irradiance_w_m2"].get<double>() +
                  j["ground_diffuse"]["irradiance_w_m2"].get<double>(),
              1e-9);
  EXPECT_EQ(j["direct"]["irradiance_w_m2"].get<double>(), 0.0);
  EXPECT_EQ(j["ground_reflection"]["model"], "isotropic");
  EXPECT_EQ(j["ground_reflection"]["albedo_source"], "ground_albedo");
  EXPECT_EQ(j["ground_reflection"]["albedo"].get<double>(), 0.3);
}

TEST_F(IrradianceGround, HorizontalPlaneGetsNone) {
  const ApiResponse r = call({{"ground_albedo", "0.3"}});
  ASSERT_EQ(r.status, 200) << r.body;
  const auto j = nlohmann::json::parse(r.body);
  EXPECT_EQ(j["ground_diffuse"]["irradiance_w_m2"].get<double>(), 0.0);
  EXPECT_NEAR(
      j["global"]["irradiance_w_m2"].get<double>(),
      j["direct"]["irradiance_w_m2"].get<double>() + j["diffuse"]["irradiance_w_m2"].get<double>(),
      1e-9);
}

TEST_F(IrradianceGround, TheModelsAlbedoSpectrumWithoutGroundAlbedo) {
  // The test sky's ground is the shared default, the spectral albedo of grass.
  const ApiResponse r = call({{"tilt", "90"}, {"surface_azimuth", "120"}});
  ASSERT_EQ(r.status, 200) << r.body;
  const auto j = nlohmann::json::parse(r.body);
  EXPECT_EQ(j["ground_reflection"]["albedo_source"], "model");
  const clearsky::testing::TestSky sky{ModelConfig{}};
  const auto grid = WavelengthGrid::paper_bins();
  for (std::size_t i = 0; i < grid.size(); ++i) {
    EXPECT_NEAR(j["ground_diffuse"]["spectral_w_m2_nm"][i].get<double>(),
                sky.atmosphere().ground_albedo[i] * ghi(grid[i]) / 2, 1e-12);
  }
}

TEST_F(IrradianceGround, ExcludedOnRequest) {
  ApiResponse r = call({{"tilt", "90"}, {"ground_reflection", "exclude"}});
  ASSERT_EQ(r.status, 200) << r.body;
  const auto j = nlohmann::json::parse(r.body);
  EXPECT_FALSE(j.contains("ground_diffuse"));
  EXPECT_EQ(j["ground_reflection"]["model"], "excluded");
  EXPECT_NEAR(
      j["global"]["irradiance_w_m2"].get<double>(),
      j["direct"]["irradiance_w_m2"].get<double>() + j["diffuse"]["irradiance_w_m2"].get<double>(),
      1e-9);
  r = call({{"ground_reflection", "exclude"}, {"ground_albedo", "0.2"}});
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(nlohmann::json::parse(r.body)["error"]["parameter"], "ground_albedo");
  r = call({{"ground_albedo", "1.5"}});
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(nlohmann::json::parse(r.body)["error"]["parameter"], "ground_albedo");
}

}  // namespace
}  // namespace clearsky::api
