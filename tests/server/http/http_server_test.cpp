// The server over loopback with a real HTTP client: each endpoint gives the numbers of the
// direct library call, errors keep the one format, health/readiness, metrics, and 8 threads x
// 200 mixed requests give identical answers without errors.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "api/handlers/handlers.h"
#include "models/colour/colour_spaces.h"
#include "models/core/numeric.h"
#include "tests/server/http/server_fixture.h"

namespace clearsky::server {
namespace {

using clearsky::testing::TestSky;

class HttpServerTest : public testing::ServerFixture {};

nlohmann::json get_json(httplib::Client& c, const std::string& path, int expected_status) {
  const auto r = c.Get(path);
  EXPECT_TRUE(r) << path;
  if (!r) return {};
  EXPECT_EQ(r->status, expected_status) << path << " " << r->body;
  return nlohmann::json::parse(r->body);
}

TEST_F(HttpServerTest, HealthAndReadiness) {
  auto c = client();
  EXPECT_EQ(get_json(c, "/healthz", 200)["status"], "ok");
  const auto ready = get_json(c, "/readyz", 200);
  EXPECT_EQ(ready["models"]["testsky"]["status"], "ready");
}

TEST_F(HttpServerTest, RadianceEqualsTheDirectCall) {
  auto c = client();
  const auto j = get_json(
      c, "/v1/radiance?model=testsky&sun_zenith=40&sun_azimuth=100&view_zenith=60&view_azimuth=10",
      200);
  const auto grid = WavelengthGrid::paper_bins();
  const SkyDirection view{degrees_to_radians(60.0), degrees_to_radians(10.0)};
  const SkyDirection sun{degrees_to_radians(40.0), degrees_to_radians(100.0)};
  ASSERT_EQ(j["samples"][0]["radiance"].size(), grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    EXPECT_EQ(j["samples"][0]["radiance"][i].get<double>(),
              TestSky::radiance(1.0, grid[i], view, sun));
  }
  const auto post =
      c.Post("/v1/radiance",
             R"({"model":"testsky","sun_zenith":40,"sun_azimuth":100,"views":[[60,10],[0,0]]})",
             "application/json");
  ASSERT_TRUE(post);
  ASSERT_EQ(post->status, 200) << post->body;
  EXPECT_EQ(nlohmann::json::parse(post->body)["samples"][0]["radiance"],
            j["samples"][0]["radiance"]);
}

TEST_F(HttpServerTest, IrradianceAndRgbEqualTheDirectCalls) {
  auto c = client();
  const auto model = tables->model(tables->factories()[0], ModelConfig{});
  const SunPosition sun{degrees_to_radians(40.0), degrees_to_radians(100.0)};
  const auto state = model->prepare_sun(sun);
  const PlaneOrientation plane{degrees_to_radians(35.0), degrees_to_radians(160.0)};
  const SpectralSample diffuse = model->sky_irradiance(*state, Viewpoint{}, plane);
  const auto j = get_json(c,
                          "/v1/"
                          "irradiance?model=testsky&sun_zenith=40&sun_azimuth=100&tilt=35&surface_"
                          "azimuth=160&spectral=true",
                          200);
  for (std::size_t i = 0; i < diffuse.value.size(); ++i) {
    EXPECT_EQ(j["diffuse"]["spectral_w_m2_nm"][i].get<double>(), diffuse.value[i]);
  }
  EXPECT_NEAR(j["diffuse"]["illuminance_lx"].get<double>(),
              spectrum_to_luminance(diffuse.value, model->wavelengths()),
              1e-9 * j["diffuse"]["illuminance_lx"].get<double>());

  SpectralBatch batch;
  const std::vector<ViewDirection> views = {{degrees_to_radians(25.0), degrees_to_radians(300.0)}};
  model->sky_radiance(*state, Viewpoint{}, views, batch);
  const Spectrum l(std::vector<double>(batch.values.begin(), batch.values.end()));
  const LinearSrgb expected = spectrum_to_linear_srgb(l, model->wavelengths());
  const auto rgb = get_json(
      c, "/v1/rgb?model=testsky&sun_zenith=40&sun_azimuth=100&view_zenith=25&view_azimuth=300",
      200);
  EXPECT_NEAR(rgb["samples"][0]["rgb"][0].get<double>(), expected.r, 1e-12);
  EXPECT_NEAR(rgb["samples"][0]["rgb"][1].get<double>(), expected.g, 1e-12);
  EXPECT_NEAR(rgb["samples"][0]["rgb"][2].get<double>(), expected.b, 1e-12);
}

TEST_F(HttpServerTest, ErrorsUseOneFormat) {
  auto c = client();
  const auto unknown = get_json(
      c,
      "/v1/"
      "radiance?model=testsky&sun_zenith=40&sun_azimuth=100&view_zenith=60&view_azimuth=10&bogus=1",
      400);
  EXPECT_EQ(unknown["error"]["parameter"], "bogus");
  EXPECT_EQ(unknown["error"]["code"], "unknown_parameter");
  EXPECT_EQ(
      get_json(c,
               "/v1/radiance?model=nope&sun_zenith=40&sun_azimuth=100&view_zenith=6&view_azimuth=1",
               404)["error"]["code"],
      "unknown_model");
  EXPECT_EQ(
      get_json(
          c,
          "/v1/radiance?model=testsky&sun_zenith=100&sun_azimuth=100&view_zenith=6&view_azimuth=1",
          422)["error"]["parameter"],
      "sun_zenith");
  EXPECT_EQ(
      get_json(
          c,
          "/v1/radiance?model=testsky&sun_zenith=NaN&sun_azimuth=100&view_zenith=6&view_azimuth=1",
          400)["error"]["parameter"],
      "sun_zenith");
  EXPECT_EQ(get_json(c, "/no/such/route", 404)["error"]["code"], "not_found");
  const auto bad_json = c.Post("/v1/rgb", "{", "application/json");
  ASSERT_TRUE(bad_json);
  EXPECT_EQ(bad_json->status, 400);
  EXPECT_EQ(nlohmann::json::parse(bad_json->body)["error"]["code"], "invalid_body");
}

TEST_F(HttpServerTest, PayloadAboveTheLimitIs413) {
  stop();
  ServerConfig config;
  config.payload_max_bytes = 1000;
  start(config);
  auto c = client();
  const auto r = c.Post("/v1/radiance", std::string(5000, ' '), "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 413);
  EXPECT_EQ(nlohmann::json::parse(r->body)["error"]["code"], "too_large");
}

TEST_F(HttpServerTest, BuildingTablesGive503WithRetryAfter) {
  stop();
  ServerConfig config;
  config.build_wait_ms = 10;
  config.retry_after_s = 3;
  start(config);
  auto c = client();
  const auto r = c.Get(
      "/v1/"
      "radiance?model=testsky&sun_zenith=40&sun_azimuth=100&view_zenith=6&view_azimuth=1&build_ms="
      "500");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 503);
  EXPECT_EQ(r->get_header_value("Retry-After"), "3");
  EXPECT_EQ(nlohmann::json::parse(r->body)["error"]["code"], "model_not_ready");
}

TEST_F(HttpServerTest, MetricsCountRequestsPerEndpointAndModel) {
  auto c = client();
  get_json(c,
           "/v1/radiance?model=testsky&sun_zenith=40&sun_azimuth=100&view_zenith=6&view_azimuth=1",
           200);
  // A request is counted after its response is sent: poll briefly.
  const std::string counted =
      R"(clearsky_http_requests_total{endpoint="/v1/radiance",model="testsky",status="200"} 1)";
  std::string body;
  for (int i = 0; i < 100 && body.find(counted) == std::string::npos; ++i) {
    if (i > 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const auto r = c.Get("/metrics");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200);
    body = r->body;
  }
  EXPECT_NE(body.find(counted), std::string::npos) << body;
  EXPECT_NE(body.find("clearsky_http_request_duration_seconds_bucket"), std::string::npos);
  EXPECT_NE(body.find(R"(clearsky_table_bytes{model="testsky"} 1234)"), std::string::npos);
}

TEST_F(HttpServerTest, ConcurrentMixedRequestsGiveIdenticalAnswers) {
  const std::vector<std::string> paths = {
      "/v1/radiance?model=testsky&sun_zenith=40&sun_azimuth=100&view_zenith=60&view_azimuth=10",
      "/v1/"
      "rgb?model=testsky&sun_zenith=40&sun_azimuth=100&view_zenith=30&view_azimuth=10&method=three",
      "/v1/irradiance?model=testsky&sun_zenith=40&sun_azimuth=100&tilt=30&surface_azimuth=180",
      "/v1/sun?lat=42.44&lon=-76.48&time=2013-05-27T11:45:00-04:00",
      "/v1/"
      "radiance?model=testsky&sun_zenith=40&sun_azimuth=100&view_zenith=60&view_azimuth=10&"
      "wavelengths=400,500",
      "/v1/models",
  };
  std::vector<std::string> expected;
  {
    auto c = client();
    for (const auto& p : paths) {
      const auto r = c.Get(p);
      ASSERT_TRUE(r);
      ASSERT_EQ(r->status, 200) << p << r->body;
      expected.push_back(r->body);
    }
  }
  std::atomic<int> failures{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t) {
    threads.emplace_back([&, t] {
      auto c = client();
      c.set_keep_alive(true);
      for (int i = 0; i < 200; ++i) {
        const std::size_t k = static_cast<std::size_t>(t + i) % paths.size();
        const auto r = c.Get(paths[k]);
        if (!r || r->status != 200 || r->body != expected[k]) ++failures;
      }
    });
  }
  for (auto& t : threads) t.join();
  EXPECT_EQ(failures, 0);
}

}  // namespace
}  // namespace clearsky::server
