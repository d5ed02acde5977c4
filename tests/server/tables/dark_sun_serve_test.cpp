// A dark sun against a real `clearsky serve` (docs/model-contract.md "Dark suns"): Haber's sky
// beyond its dark_beyond_sun_zenith_deg is answered at once with zeros by radiance, rgb,
// irradiance and skydome, while a lit sun needs its per-sun state. --build-wait-ms 0 makes the
// difference visible without timing: a request that needed a per-sun preparation would get 503.
#include <gtest/gtest.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "tests/server/http/watched_serve_process.h"

namespace clearsky::server {
namespace {

using testing::WatchedServeProcess;

// Every number in the JSON value.
void collect_numbers(const nlohmann::json& j, std::vector<double>& out) {
  if (j.is_number()) out.push_back(j.get<double>());
  if (j.is_array() || j.is_object())
    for (const auto& item : j) collect_numbers(item, out);
}

TEST(DarkSunServe, HaberAnswersANightSkyAtOnceWithZeros) {
  WatchedServeProcess server(
      {"--models", "haber", "--prebuild-three", "false", "--build-wait-ms", "0"});
  ASSERT_GT(server.port(), 0) << server.log();
  auto c = server.client(90);
  bool ready = false;
  for (int i = 0; i < 1200 && !ready; ++i) {
    const auto r = c.Get("/readyz");
    ready = r && r->status == 200;
    if (!ready) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_TRUE(ready) << server.log();

  const auto models = c.Get("/v1/models");
  ASSERT_TRUE(models && models->status == 200);
  const auto declared = nlohmann::json::parse(
      models->body)["models"][0]["capabilities"]["dark_beyond_sun_zenith_deg"];
  ASSERT_TRUE(declared.is_number()) << models->body;
  EXPECT_LT(declared.get<double>(), 151.0);

  const std::string sun = "model=haber&sun_zenith=151&sun_azimuth=30";
  for (const std::string& target :
       {"/v1/radiance?" + sun + "&view_zenith=85&view_azimuth=30",
        "/v1/rgb?" + sun + "&view_zenith=89.9&view_azimuth=30",
        "/v1/irradiance?" + sun + "&tilt=90&surface_azimuth=30&spectral=true"}) {
    const auto r = c.Get(target);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << target << ": " << r->body;
    const auto body = nlohmann::json::parse(r->body);
    std::vector<double> answered;
    for (const char* key : {"samples", "direct", "diffuse", "global"})
      if (body.contains(key)) collect_numbers(body[key], answered);
    ASSERT_FALSE(answered.empty()) << r->body;
    for (double v : answered) {
      // The views' angles are echoed; every radiometric number is zero.
      EXPECT_TRUE(v == 0.0 || v == 85.0 || v == 89.9 || v == 30.0) << target << ": " << r->body;
    }
  }
  const auto dome = c.Get("/v1/skydome?" + sun + "&size=32");
  ASSERT_TRUE(dome);
  EXPECT_EQ(dome->status, 200) << dome->body;

  // A lit sun needs its per-sun state, which no request waits for here.
  const auto lit = c.Get(
      "/v1/radiance?model=haber&sun_zenith=60&sun_azimuth=30&view_zenith=85&"
      "view_azimuth=30");
  ASSERT_TRUE(lit);
  EXPECT_EQ(lit->status, 503) << lit->body;
  EXPECT_TRUE(server.alive());
}

}  // namespace
}  // namespace clearsky::server
