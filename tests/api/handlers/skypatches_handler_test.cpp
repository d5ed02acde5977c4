// GET /v1/skypatches without transport on the analytic test sky
// (tests/support/test_sky_model.h), whose patch averages have a closed form: the JSON and CSV
// answers in Radiance's patch order, the sun handled both ways, the three outputs, and every
// refusal naming its parameter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "api/colour/radiance_rgb.h"
#include "api/handlers/handlers.h"
#include "tests/support/synchronous_provider.h"
#include "tests/support/test_sky_model.h"

namespace clearsky::api {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
using Q = std::vector<std::pair<std::string, std::string>>;

class SkyPatchesHandler : public ::testing::Test {
 protected:
  ApiResponse call(Q query) {
    ApiRequest r{"GET", "/v1/skypatches", std::move(query), ""};
    const ApiContext context{provider, limits};
    try {
      return skypatches(context, r);
    } catch (const ApiError& e) {
      return error_response(e);
    }
  }
  nlohmann::json ok(Q extra) {
    Q q{{"model", "testsky"}, {"sun_zenith", "35"}, {"sun_azimuth", "120"}};
    q.insert(q.end(), extra.begin(), extra.end());
    const ApiResponse r = call(q);
    EXPECT_EQ(r.status, 200) << r.body;
    return r.status == 200 ? nlohmann::json::parse(r.body) : nlohmann::json{};
  }
  void refused(Q extra, int status, const std::string& parameter) {
    Q q{{"model", "testsky"}, {"sun_zenith", "35"}, {"sun_azimuth", "120"}};
    q.insert(q.end(), extra.begin(), extra.end());
    const ApiResponse r = call(q);
    EXPECT_EQ(r.status, status) << r.body;
    EXPECT_EQ(nlohmann::json::parse(r.body)["error"]["parameter"], parameter) << r.body;
  }

  clearsky::testing::SynchronousProvider provider{clearsky::testing::test_factories()};
  Limits limits{100, 500, 1024};
};

// The test sky's radiance integrated over a band patch in closed form, over its solid angle:
// L = c (1 + u + 0.5 sqrt(1 - u^2) cos(phi - phi_sun)), u = cos(zenith) = sin(altitude).
double test_sky_patch_average(double c, double alt0, double alt1, double az0, double az1,
                              double sun_azimuth) {
  const double u0 = std::sin(alt0), u1 = std::sin(alt1);
  const auto root_integral = [](double u) {
    return 0.5 * (u * std::sqrt(1.0 - u * u) + std::asin(u));
  };
  const double integral = (az1 - az0) * ((u1 - u0) + 0.5 * (u1 * u1 - u0 * u0)) +
                          0.5 * (root_integral(u1) - root_integral(u0)) *
                              (std::sin(az1 - sun_azimuth) - std::sin(az0 - sun_azimuth));
  return c * integral / ((az1 - az0) * (u1 - u0));
}

TEST_F(SkyPatchesHandler, TregenzaPatchesAreTheClosedFormAverages) {
  const auto j = ok({{"wavelengths", "500"}});
  ASSERT_EQ(j["patch_count"], 146);
  ASSERT_EQ(j["patches"].size(), 146u);
  EXPECT_EQ(j["scheme"], "tregenza");
  EXPECT_EQ(j["unit"], "W/(m2.sr.nm)");
  const double c = 0.01;  // gain 1, turbidity 2.53, 500 nm
  const double band = 12.0 * kDeg;
  // Patches 1..144 in Radiance's order: bands of 30, 30, 24, 24, 18, 12 and 6 from North.
  const int per_band[] = {30, 30, 24, 24, 18, 12, 6};
  std::size_t k = 1;
  for (int r = 0; r < 7; ++r) {
    const double width = 2.0 * kPi / per_band[r];
    for (int col = 0; col < per_band[r]; ++col, ++k) {
      const auto& patch = j["patches"][k];
      ASSERT_EQ(patch["patch"], k);
      EXPECT_NEAR(patch["altitude_deg"].get<double>(), 12.0 * r + 6.0, 1e-9);
      EXPECT_NEAR(patch["azimuth_deg"].get<double>(), col * 360.0 / per_band[r], 1e-9);
      const double expected = test_sky_patch_average(
          c, r * band, (r + 1) * band, (col - 0.5) * width, (col + 0.5) * width, 120.0 * kDeg);
      EXPECT_NEAR(patch["value"][0].get<double>(), expected, 1e-12) << k;
    }
  }
  // The cap: the azimuthal term averages out.
  const double u0 = std::sin(84.0 * kDeg);
  EXPECT_NEAR(j["patches"][145]["value"][0].get<double>(), c * (1.0 + 0.5 * (1.0 + u0)), 1e-12);
  // Diffuse horizontal of the vector against the closed form c (pi + 2 pi / 3) over the bin.
  EXPECT_EQ(j["sun_patch"], 1 + 30 + 30 + 24 + 24 + 6);  // altitude 55 (band 5), azimuth 120
  ASSERT_FALSE(j["sun_source"].is_null());
  EXPECT_NEAR(
      j["sun_source"]["value"][0].get<double>() * j["sun_source"]["solid_angle_sr"].get<double>(),
      1.5, 1e-12);
  const auto& d = j["sun_source"]["direction"];
  EXPECT_NEAR(d[0].get<double>(), std::sin(35 * kDeg) * std::sin(120 * kDeg), 1e-12);
  EXPECT_NEAR(d[1].get<double>(), std::sin(35 * kDeg) * std::cos(120 * kDeg), 1e-12);
  EXPECT_NEAR(d[2].get<double>(), std::cos(35 * kDeg), 1e-12);
  // The ground: 0.2 (1.5 cos 35 + c (pi + 2 pi / 3)) / pi at 500 nm.
  EXPECT_NEAR(j["patches"][0]["value"][0].get<double>(),
              0.2 * (1.5 * std::cos(35 * kDeg) + c * (kPi + 2 * kPi / 3)) / kPi, 1e-9);
  EXPECT_EQ(j["patches"][0]["altitude_deg"], -90.0);
}

TEST_F(SkyPatchesHandler, ReinhartAndTheSunInItsPatch) {
  const auto j =
      ok({{"scheme", "reinhart"}, {"mf", "2"}, {"sun", "patch"}, {"wavelengths", "500"}});
  ASSERT_EQ(j["patch_count"], 578);
  EXPECT_TRUE(j["sun_source"].is_null());
  const auto separate = ok({{"scheme", "reinhart"}, {"mf", "2"}, {"wavelengths", "500"}});
  const std::size_t k = j["sun_patch"];
  EXPECT_EQ(k, separate["sun_patch"].get<std::size_t>());
  const double added =
      j["patches"][k]["value"][0].get<double>() - separate["patches"][k]["value"][0].get<double>();
  EXPECT_NEAR(added * j["patches"][k]["solid_angle_sr"].get<double>(), 1.5, 1e-9);
}

TEST_F(SkyPatchesHandler, RgbAndLuminance) {
  const auto rgb = ok({{"output", "rgb"}});
  const auto lum = ok({{"output", "luminance"}});
  EXPECT_EQ(rgb["unit"], "W/(m2.sr)");
  EXPECT_EQ(lum["unit"], "cd/m2");
  EXPECT_EQ(rgb["gamut_mapping"], "negative components clipped to 0");
  EXPECT_FALSE(rgb.contains("wavelengths_nm"));
  for (std::size_t k : {0u, 1u, 77u, 145u}) {
    const auto& c = rgb["patches"][k]["value"];
    ASSERT_EQ(c.size(), 3u);
    const double luminance = lum["patches"][k]["value"].get<double>();
    EXPECT_GT(luminance, 0.0);
    // Radiance's luminance of the RGB is the patch's (no clipping on this sky).
    EXPECT_NEAR(radiance_rgb_luminance({c[0], c[1], c[2]}), luminance, 1e-9 * luminance);
  }
}

TEST_F(SkyPatchesHandler, CsvHasOneRowPerPatchThenTheSun) {
  Q q{{"model", "testsky"},
      {"sun_zenith", "35"},
      {"sun_azimuth", "120"},
      {"format", "csv"},
      {"output", "luminance"}};
  ApiResponse r = call(q);
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.content_type, "text/csv");
  std::istringstream lines(r.body);
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(lines, line)) rows.push_back(line);
  ASSERT_EQ(rows.size(), 1u + 146u + 1u);
  EXPECT_EQ(rows[0], "patch,altitude_deg,azimuth_deg,solid_angle_sr,luminance_cd_m2");
  EXPECT_EQ(rows[1].substr(0, 5), "0,-90");
  EXPECT_EQ(rows[2].substr(0, 4), "1,6,");
  EXPECT_EQ(rows.back().substr(0, 4), "sun,");
  q.emplace_back("sun", "patch");
  r = call(q);
  EXPECT_EQ(std::count(r.body.begin(), r.body.end(), '\n'), 147);
}

TEST_F(SkyPatchesHandler, RefusalsNameTheParameter) {
  refused({{"mf", "2"}}, 400, "mf");  // mf belongs to scheme=reinhart
  refused({{"scheme", "reinhart"}, {"mf", "7"}}, 400, "mf");
  refused({{"scheme", "reinhart"}, {"mf", "1.5"}}, 400, "mf");
  refused({{"scheme", "klems"}}, 400, "scheme");
  refused({{"sun", "both"}}, 400, "sun");
  refused({{"output", "xyz"}}, 400, "output");
  refused({{"output", "rgb"}, {"wavelengths", "500"}}, 400, "wavelengths");
  refused({{"ground_reflectance", "1.5"}}, 400, "ground_reflectance");
  refused({{"format", "xml"}}, 400, "format");
  refused({{"view_zenith", "10"}}, 400, "view_zenith");
  // 5186 patches x 200 wavelengths is above the 1e6 values of one sky vector.
  refused({{"scheme", "reinhart"}, {"mf", "6"}, {"wavelengths", "400:599:1"}}, 413, "wavelengths");
  const ApiResponse below =
      call({{"model", "testsky"}, {"sun_zenith", "100"}, {"sun_azimuth", "0"}});
  EXPECT_EQ(below.status, 422) << below.body;
}

}  // namespace
}  // namespace clearsky::api
