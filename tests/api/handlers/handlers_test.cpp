// The JSON/CSV handlers against direct library calls on the analytic test sky (closed-form
// answers), and every error case: unknown/misspelt/conflicting parameters, NaN, unknown model,
// requests the model's capabilities exclude, limits.
#include "api/handlers/handlers.h"

#include <gtest/gtest.h>

#include <cmath>

#include "api/colour/colour_wavelengths.h"
#include "api/colour/xyz_weights.h"
#include "models/colour/three_wavelength_rgb.h"
#include "models/core/numeric.h"
#include "tests/support/place_time_cases.h"
#include "tests/support/synchronous_provider.h"
#include "tests/support/test_sky_model.h"

namespace clearsky::api {
namespace {

using clearsky::testing::TestSky;

class Handlers : public ::testing::Test {
 protected:
  ApiResponse call(ApiResponse (*handler)(const ApiContext&, const ApiRequest&),
                   const std::string& method, const std::string& path,
                   std::vector<std::pair<std::string, std::string>> query,
                   const std::string& body = "") {
    ApiRequest r{method, path, std::move(query), body};
    const ApiContext context{provider, limits};
    try {
      return handler(context, r);
    } catch (const ApiError& e) {
      return error_response(e);
    }
  }
  nlohmann::json json_of(const ApiResponse& r) { return nlohmann::json::parse(r.body); }
  void expect_error(const ApiResponse& r, int status, const std::string& parameter) {
    EXPECT_EQ(r.status, status) << r.body;
    const auto j = json_of(r);
    ASSERT_TRUE(j.contains("error")) << r.body;
    EXPECT_EQ(j["error"]["parameter"], parameter) << r.body;
    EXPECT_FALSE(j["error"]["message"].get<std::string>().empty());
  }

  clearsky::testing::SynchronousProvider provider{clearsky::testing::test_factories()};
  Limits limits{100, 500, 1024};
  using Q = std::vector<std::pair<std::string, std::string>>;
  const Q sun{{"model", "testsky"}, {"sun_zenith", "30"}, {"sun_azimuth", "120"}};
  Q with(Q extra) const {
    Q q = sun;
    q.insert(q.end(), extra.begin(), extra.end());
    return q;
  }
};

TEST_F(Handlers, RadianceMatchesTheModel) {
  const ApiResponse r =
      call(radiance, "GET", "/v1/radiance", with({{"view_zenith", "45"}, {"view_azimuth", "200"}}));
  ASSERT_EQ(r.status, 200) << r.body;
  const auto j = json_of(r);
  const auto grid = WavelengthGrid::paper_bins();
  ASSERT_EQ(j["wavelengths_nm"].size(), grid.size());
  const SkyDirection view{degrees_to_radians(45.0), degrees_to_radians(200.0)};
  const SkyDirection s{degrees_to_radians(30.0), degrees_to_radians(120.0)};
  for (std::size_t i = 0; i < grid.size(); ++i) {
    EXPECT_DOUBLE_EQ(j["wavelengths_nm"][i].get<double>(), grid[i]);
    EXPECT_NEAR(j["samples"][0]["radiance"][i].get<double>(),
                TestSky::radiance(1.0, grid[i], view, s), 1e-15);
  }
  EXPECT_EQ(j["grid"], "bins");
  EXPECT_EQ(j["sun"]["source"], "given");
}

TEST_F(Handlers, RadianceOnRequestedWavelengths) {
  // On the default grid: a subset of its bins.
  auto r = call(
      radiance, "GET", "/v1/radiance",
      with({{"view_zenith", "10"}, {"view_azimuth", "0"}, {"wavelengths", "360:383.5:11.75"}}));
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(json_of(r)["wavelengths_nm"], nlohmann::json({360.0, 371.75, 383.5}));
  // Elsewhere: a model built on exactly those points.
  r = call(radiance, "GET", "/v1/radiance",
           with({{"view_zenith", "10"}, {"view_azimuth", "0"}, {"wavelengths", "400,500.5,700"}}));
  ASSERT_EQ(r.status, 200) << r.body;
  const auto j = json_of(r);
  EXPECT_EQ(j["grid"], "points");
  const SkyDirection view{degrees_to_radians(10.0), 0.0};
  const SkyDirection s{degrees_to_radians(30.0), degrees_to_radians(120.0)};
  EXPECT_NEAR(j["samples"][0]["radiance"][1].get<double>(), TestSky::radiance(1.0, 500.5, view, s),
              1e-15);
}

TEST_F(Handlers, RadianceBatchAndCsv) {
  const std::string body =
      R"({"model": "testsky", "sun_zenith": 30, "sun_azimuth": 120, "views": [[0, 0], {"view_zenith": 80, "view_azimuth": 300}], "wavelengths": "550"})";
  auto r = call(radiance, "POST", "/v1/radiance", {}, body);
  ASSERT_EQ(r.status, 200) << r.body;
  const auto j = json_of(r);
  ASSERT_EQ(j["samples"].size(), 2u);
  const SkyDirection s{degrees_to_radians(30.0), degrees_to_radians(120.0)};
  EXPECT_NEAR(
      j["samples"][1]["radiance"][0].get<double>(),
      TestSky::radiance(1.0, 550.0, {degrees_to_radians(80.0), degrees_to_radians(300.0)}, s),
      1e-15);
  r = call(radiance, "GET", "/v1/radiance",
           with({{"view_zenith", "0"},
                 {"view_azimuth", "0"},
                 {"wavelengths", "500,600"},
                 {"format", "csv"}}));
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(r.content_type, "text/csv");
  EXPECT_EQ(r.body,
            "view_zenith_deg,view_azimuth_deg,wavelength_nm,radiance_w_m2_sr_nm\n0,0,500,0.02\n0,0,"
            "600,0.024\n");
}

TEST_F(Handlers, AtmosphereOverridesSelectOtherTables) {
  const auto r = call(radiance, "GET", "/v1/radiance",
                      with({{"view_zenith", "0"},
                            {"view_azimuth", "0"},
                            {"wavelengths", "500"},
                            {"turbidity", "5.06"},
                            {"gain", "2"}}));
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_NEAR(json_of(r)["samples"][0]["radiance"][0].get<double>(), 2.0 * 2.0 * 0.02, 1e-15);
}

TEST_F(Handlers, ErrorsNameTheParameter) {
  const Q view{{"view_zenith", "45"}, {"view_azimuth", "0"}};
  auto q = [&](Q extra) {
    Q x = view;
    x.insert(x.end(), extra.begin(), extra.end());
    return x;
  };
  expect_error(call(radiance, "GET", "/v1/radiance", with(q({{"sun_zenit", "3"}}))), 400,
               "sun_zenit");
  expect_error(
      call(radiance, "GET", "/v1/radiance", with({{"view_zenith", "nan"}, {"view_azimuth", "0"}})),
      400, "view_zenith");
  expect_error(call(radiance, "GET", "/v1/radiance", with({{"view_zenith", "45"}})), 400,
               "view_azimuth");
  expect_error(call(radiance, "GET", "/v1/radiance", with(q({{"lat", "40"}}))), 400, "lat");
  // A cacheable sky answer never depends on the clock: time has no default here.
  expect_error(call(radiance, "GET", "/v1/radiance",
                    q({{"model", "testsky"}, {"lat", "40"}, {"lon", "-76"}})),
               400, "time");
  expect_error(call(radiance, "GET", "/v1/radiance",
                    q({{"model", "nope"}, {"sun_zenith", "3"}, {"sun_azimuth", "3"}})),
               404, "model");
  expect_error(call(radiance, "GET", "/v1/radiance",
                    q({{"model", "testsky"}, {"sun_zenith", "95"}, {"sun_azimuth", "3"}})),
               422, "sun_zenith");
  expect_error(
      call(radiance, "GET", "/v1/radiance", with({{"view_zenith", "100"}, {"view_azimuth", "0"}})),
      422, "view_zenith");
  expect_error(call(radiance, "GET", "/v1/radiance", with(q({{"altitude", "5000"}}))), 422,
               "altitude");
  expect_error(call(radiance, "GET", "/v1/radiance", with(q({{"wavelengths", "300,400"}}))), 422,
               "wavelengths");
  expect_error(call(radiance, "GET", "/v1/radiance", with(q({{"wavelengths", "400,300"}}))), 400,
               "wavelengths");
  expect_error(call(radiance, "GET", "/v1/radiance", with(q({{"wavelengths", "360:830:0.1"}}))),
               413, "wavelengths");
  expect_error(call(radiance, "GET", "/v1/radiance", with(q({{"turbidity", "11"}}))), 400,
               "turbidity");
  // alpha is not a parameter of this model: unused, hence an error.
  expect_error(call(radiance, "GET", "/v1/radiance", with(q({{"alpha", "1"}}))), 400, "alpha");
  expect_error(call(radiance, "GET", "/v1/radiance", with(q({{"format", "xml"}}))), 400, "format");
  std::string many = R"({"model": "testsky", "sun_zenith": 30, "sun_azimuth": 120, "views": [)";
  for (int i = 0; i < 101; ++i) many += std::string(i ? "," : "") + "[10, 10]";
  expect_error(call(radiance, "POST", "/v1/radiance", {}, many + "]}"), 413, "views");
  expect_error(
      call(
          radiance, "POST", "/v1/radiance", {},
          R"({"model": "testsky", "sun_zenith": 30, "sun_azimuth": 120, "views": [[10, 10], [120, 0]]})"),
      422, "views[1]");
  const auto bad_body = call(radiance, "POST", "/v1/radiance", {}, "{not json");
  EXPECT_EQ(bad_body.status, 400);
}

TEST_F(Handlers, PlaceAndTimeGiveTheSunThroughSpa) {
  const auto r = call(radiance, "GET", "/v1/radiance",
                      {{"model", "testsky"},
                       {"lat", "42.44"},
                       {"lon", "-76.48"},
                       {"time", "2013-05-27T11:45:00-04:00"},
                       {"view_zenith", "0"},
                       {"view_azimuth", "0"},
                       {"wavelengths", "500"}});
  ASSERT_EQ(r.status, 200) << r.body;
  const auto j = json_of(r);
  EXPECT_EQ(j["sun"]["source"], "spa");
  EXPECT_NEAR(j["sun"]["zenith_deg"].get<double>(), 26.64, 0.02);
  EXPECT_NEAR(j["sun"]["azimuth_deg"].get<double>(), 136.07, 0.02);
  // At night the test sky (sun above the horizon only) cannot answer: 422 naming time.
  expect_error(call(radiance, "GET", "/v1/radiance",
                    {{"model", "testsky"},
                     {"lat", "42.44"},
                     {"lon", "-76.48"},
                     {"time", "2013-05-27T23:45:00-04:00"},
                     {"view_zenith", "0"},
                     {"view_azimuth", "0"}}),
               422, "time");
}

TEST_F(Handlers, IrradianceOfTheAnalyticSky) {
  auto r = call(irradiance, "GET", "/v1/irradiance", with({{"spectral", "true"}}));
  ASSERT_EQ(r.status, 200) << r.body;
  auto j = json_of(r);
  const auto grid = WavelengthGrid::paper_bins();
  double diffuse_total = 0, direct_total = 0;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const double base = 0.01 * grid[i] / 500.0;
    // Uniform + cos(theta) terms: pi + 2 pi / 3; the azimuthal term integrates to zero.
    EXPECT_NEAR(j["diffuse"]["spectral_w_m2_nm"][i].get<double>(), base * 5.0 * kPi / 3.0, 1e-12);
    EXPECT_NEAR(j["direct"]["spectral_w_m2_nm"][i].get<double>(),
                1.5 * grid[i] / 500.0 * std::cos(degrees_to_radians(30.0)), 1e-12);
    diffuse_total += 11.75 * base * 5.0 * kPi / 3.0;
    direct_total += 11.75 * 1.5 * grid[i] / 500.0 * std::cos(degrees_to_radians(30.0));
  }
  EXPECT_NEAR(j["diffuse"]["irradiance_w_m2"].get<double>(), diffuse_total, 1e-9);
  EXPECT_NEAR(j["global"]["irradiance_w_m2"].get<double>(), diffuse_total + direct_total, 1e-9);
  EXPECT_GT(j["global"]["illuminance_lx"].get<double>(),
            j["diffuse"]["illuminance_lx"].get<double>());
  // A vertical plane facing the sun's azimuth: direct = DNI sin(sun zenith).
  r = call(irradiance, "GET", "/v1/irradiance",
           with({{"tilt", "90"},
                 {"surface_azimuth", "120"},
                 {"component", "direct"},
                 {"spectral", "true"}}));
  ASSERT_EQ(r.status, 200) << r.body;
  j = json_of(r);
  EXPECT_NEAR(j["direct"]["spectral_w_m2_nm"][0].get<double>(), 1.5 * 360.0 / 500.0 * 0.5, 1e-12);
  EXPECT_FALSE(j.contains("diffuse"));
  expect_error(call(irradiance, "GET", "/v1/irradiance", with({{"tilt", "-1"}})), 400, "tilt");
}

TEST_F(Handlers, IrradianceSaysWhyAModelCannotGoBroadband) {
  // The analytic test sky has no Angstrom aerosols to continue beyond its range: its answer
  // keeps its model-range figures (and their deprecated alias) and names why there is no
  // broadband figure instead of giving a smaller number under that name.
  const auto r = call(irradiance, "GET", "/v1/irradiance",
                      with({{"precipitable_water_cm", "2.5"}, {"ozone_atm_cm", "0.3"}}));
  ASSERT_EQ(r.status, 200) << r.body;
  const auto j = json_of(r);
  EXPECT_TRUE(j["broadband"].is_null());
  EXPECT_NE(j["broadband_unavailable"].get<std::string>().find("testsky"), std::string::npos);
  for (const char* part : {"direct_normal", "direct", "diffuse", "global"}) {
    EXPECT_TRUE(j[part]["broadband_irradiance_w_m2"].is_null()) << part;
    EXPECT_EQ(j[part]["irradiance_w_m2"], j[part]["model_range_irradiance_w_m2"]) << part;
  }
  expect_error(call(irradiance, "GET", "/v1/irradiance", with({{"precipitable_water_cm", "-1"}})),
               400, "precipitable_water_cm");
  expect_error(call(irradiance, "GET", "/v1/irradiance", with({{"ozone_atm_cm", "2"}})), 400,
               "ozone_atm_cm");
}

TEST_F(Handlers, RgbSpectralAndThreeWavelengthAgreeOnLuminance) {
  auto spectral =
      call(rgb, "GET", "/v1/rgb", with({{"view_zenith", "20"}, {"view_azimuth", "90"}}));
  auto three = call(rgb, "GET", "/v1/rgb",
                    with({{"view_zenith", "20"}, {"view_azimuth", "90"}, {"method", "three"}}));
  ASSERT_EQ(spectral.status, 200) << spectral.body;
  ASSERT_EQ(three.status, 200) << three.body;
  const auto s = json_of(spectral)["samples"][0];
  const auto t = json_of(three)["samples"][0];
  // The spectral path equals XYZ integration of the model's spectrum.
  const SkyDirection view{degrees_to_radians(20.0), degrees_to_radians(90.0)};
  const SkyDirection sun_dir{degrees_to_radians(30.0), degrees_to_radians(120.0)};
  const auto grid = WavelengthGrid::paper_bins();
  Spectrum l(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i)
    l[i] = TestSky::radiance(1.0, grid[i], view, sun_dir);
  EXPECT_NEAR(s["luminance_cd_m2"].get<double>(), spectrum_to_luminance(l, grid), 1e-9);
  const LinearSrgb c = spectrum_to_linear_srgb(l, grid);
  EXPECT_NEAR(s["rgb"][0].get<double>(), c.r, 1e-12);
  // The 3-wavelength path is k_c L(lambda_c).
  const ThreeWavelengthRgb method;
  EXPECT_NEAR(t["rgb"][1].get<double>(),
              method.k()[1] * TestSky::radiance(1.0, 550.0, view, sun_dir), 1e-12);
  // Both estimate the same luminance, within the method's approximation.
  EXPECT_NEAR(t["luminance_cd_m2"].get<double>() / s["luminance_cd_m2"].get<double>(), 1.0, 0.5);
}

// quality=draft computes the colour on the 9 colour wavelengths with the interpolating weights
// and says so; standard stays the 40-wavelength colour without the new members
// (docs/quality-levels.md "Colour wavelengths").
TEST_F(Handlers, RgbDraftStatesItsColourWavelengths) {
  const auto draft =
      call(rgb, "GET", "/v1/rgb",
           with({{"view_zenith", "20"}, {"view_azimuth", "90"}, {"quality", "draft"}}));
  const auto standard =
      call(rgb, "GET", "/v1/rgb",
           with({{"view_zenith", "20"}, {"view_azimuth", "90"}, {"quality", "standard"}}));
  ASSERT_EQ(draft.status, 200) << draft.body;
  ASSERT_EQ(standard.status, 200) << standard.body;
  const auto d = json_of(draft);
  EXPECT_EQ(d["colour_wavelengths_nm"].get<std::vector<double>>(), kDraftColourWavelengthsNm);
  EXPECT_TRUE(d["colour_error"].is_null());  // the test model has no measured figure
  EXPECT_FALSE(json_of(standard).contains("colour_wavelengths_nm"));
  const SkyDirection view{degrees_to_radians(20.0), degrees_to_radians(90.0)};
  const SkyDirection sun_dir{degrees_to_radians(30.0), degrees_to_radians(120.0)};
  const auto grid = WavelengthGrid::points(kDraftColourWavelengthsNm);
  Spectrum l(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i)
    l[i] = TestSky::radiance(1.0, grid[i], view, sun_dir);
  const Xyz xyz = XyzWeights::interpolating(grid).xyz(l.values());
  EXPECT_NEAR(d["samples"][0]["luminance_cd_m2"].get<double>(), kMaxLuminousEfficacy * xyz.y,
              1e-9 * kMaxLuminousEfficacy * xyz.y);
}

TEST_F(Handlers, ModelsListsDescriptorAndState) {
  const auto r = call(get_models, "GET", "/v1/models", {});
  ASSERT_EQ(r.status, 200);
  const auto j = json_of(r);
  ASSERT_EQ(j["models"].size(), 1u);
  EXPECT_EQ(j["models"][0]["id"], "testsky");
  EXPECT_TRUE(j["models"][0].contains("state"));
  expect_error(call(get_models, "GET", "/v1/models", {{"verbose", "1"}}), 400, "verbose");
}

TEST_F(Handlers, SunEndpoint) {
  const auto r = call(get_sun, "GET", "/v1/sun",
                      {{"lat", "42.44"}, {"lon", "-76.48"}, {"time", "2013-05-27T11:45:00-04:00"}});
  ASSERT_EQ(r.status, 200) << r.body;
  const auto j = json_of(r);
  EXPECT_NEAR(j["zenith"].get<double>(), 26.64, 0.02);
  EXPECT_EQ(j["sunrise"].get<std::string>().substr(0, 11), "2013-05-27T");
  expect_error(call(get_sun, "GET", "/v1/sun", {{"lat", "42.44"}}), 400, "lon");
  expect_error(call(get_sun, "GET", "/v1/sun", {{"lat", "42.44"}, {"lon", "1"}, {"bogus", "1"}}),
               400, "bogus");
}

// GET /v1/sun and the sky endpoints read place and time through one table: the same values are
// accepted and the same refused, naming the parameter.
TEST_F(Handlers, SameRangesOnSunAndRadiance) {
  for (const auto& c : clearsky::testing::place_time_cases()) {
    const std::string label = c.parameter + "=" + c.value;
    // delta_t given: the years after 3000 have no computed default (models/solar/delta_t.h).
    Q place{{"lat", "42.44"},
            {"lon", "-76.48"},
            {"time", "2013-05-27T11:45:00-04:00"},
            {"delta_t", "69"}};
    std::erase_if(place, [&](const auto& pair) { return pair.first == c.parameter; });
    place.emplace_back(c.parameter, c.value);
    Q sky{
        {"model", "testsky"}, {"view_zenith", "0"}, {"view_azimuth", "0"}, {"wavelengths", "500"}};
    sky.insert(sky.end(), place.begin(), place.end());
    const ApiResponse sun_answer = call(get_sun, "GET", "/v1/sun", place);
    const ApiResponse sky_answer = call(radiance, "GET", "/v1/radiance", sky);
    if (c.accepted) {
      EXPECT_EQ(sun_answer.status, 200) << label << " " << sun_answer.body;
      // The test sky may not answer (night, altitude above 1000 m): a 422, never a 400.
      EXPECT_NE(sky_answer.status, 400) << label << " " << sky_answer.body;
    } else {
      expect_error(sun_answer, 400, c.parameter);
      expect_error(sky_answer, 400, c.parameter);
    }
  }
}

// A model-side refusal (clearsky::InvalidInput) names the request parameter: a descriptor whose
// alpha range is wider than the atmosphere's lets alpha=5 reach AtmosphereParameters::validate.
TEST_F(Handlers, ModelRefusalsNameTheRequestParameter) {
  static const ModelDescriptor wide = [] {
    ModelDescriptor d = clearsky::testing::test_sky_descriptor();
    d.id = "widesky";
    d.parameters.push_back({"alpha", "", "Angstrom exponent", 0.8, 0.0, 10.0, false, true});
    return d;
  }();
  clearsky::testing::SynchronousProvider wide_provider{
      {ModelFactory{&wide, &clearsky::testing::create_test_sky, nullptr}}};
  const ApiContext context{wide_provider, limits};
  const auto answer = [&](Q query) {
    try {
      return radiance(context, ApiRequest{"GET", "/v1/radiance", std::move(query), ""});
    } catch (const ApiError& e) {
      return error_response(e);
    }
  };
  const Q base{{"model", "widesky"}, {"sun_zenith", "30"},  {"sun_azimuth", "120"},
               {"view_zenith", "0"}, {"view_azimuth", "0"}, {"wavelengths", "500"}};
  Q q = base;
  q.emplace_back("alpha", "3");
  EXPECT_EQ(answer(q).status, 200) << answer(q).body;
  q = base;
  q.emplace_back("alpha", "5");
  expect_error(answer(q), 400, "alpha");
}

}  // namespace
}  // namespace clearsky::api
