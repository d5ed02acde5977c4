// measured_aerosols' standard tables built on first use (ModelFactory::standard_on_first_use,
// docs/quality-levels.md "Serving at once") through the real `clearsky serve` with the default
// start builds: /readyz answers 200 with its draft ready and its standard not_built; its first
// standard request is answered 200 from the draft (served_quality draft) and starts the
// standard build; later answers come from the standard. Deadlines are generous (a Bruneton-engine
// standard build takes minutes on the loaded machine); nothing asserts a duration.
#include <gtest/gtest.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "tests/server/http/hostile_clients.h"
#include "tests/server/http/watched_serve_process.h"
#include "tests/support/sanitizers.h"

namespace clearsky::server {
namespace {

using testing::WatchedServeProcess;

const std::string kRadiance =
    "/v1/radiance?model=measured_aerosols&sun_zenith=40&sun_azimuth=135&view_zenith=50&"
    "view_azimuth=200";

TEST(StandardOnFirstUseServe, MeasuredAerosolsIsAnsweredFromItsDraftThenFromItsStandard) {
  WatchedServeProcess server({"--models", "measured_aerosols", "--retry-after", "1"});
  ASSERT_GT(server.port(), 0) << server.log();
  ASSERT_TRUE(testing::ready(server.port(), std::chrono::seconds(600))) << server.log();
  auto c = server.client(120);

  const auto ready = c.Get("/readyz");
  ASSERT_TRUE(ready);
  ASSERT_EQ(ready->status, 200) << ready->body;
  const auto model = nlohmann::json::parse(ready->body)["models"]["measured_aerosols"];
  EXPECT_EQ(model["levels"]["draft"]["status"], "ready") << model;
  EXPECT_EQ(model["levels"]["standard"]["status"], "not_built") << model;
  EXPECT_EQ(model["status"], "not_built") << model;

  const auto first = c.Get(kRadiance);
  ASSERT_TRUE(first);
  ASSERT_EQ(first->status, 200) << first->body;
  const auto answer = nlohmann::json::parse(first->body);
  EXPECT_EQ(answer["quality"], "standard");
  EXPECT_EQ(answer["served_quality"], "draft");
  EXPECT_EQ(first->get_header_value("Cache-Control"), "no-store");

  // The request started the standard build.
  const auto building = c.Get("/readyz");
  ASSERT_TRUE(building);
  const std::string standard = nlohmann::json::parse(
      building->body)["models"]["measured_aerosols"]["levels"]["standard"]["status"];
  EXPECT_NE(standard, "not_built") << building->body;
  // In the sanitizer tree the standard build (Bruneton's engine at the paper's resolution, every
  // load instrumented, -O1) took over ten minutes of the 2-core run: there the test ends once the
  // build has started, and the Release pass waits for its answer below.
  if (clearsky::testing::kAddressSanitizer) return;

  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(800);
  std::string served = "draft";
  while (served == "draft" && std::chrono::steady_clock::now() < deadline && server.alive()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const auto r = c.Get(kRadiance);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    served = nlohmann::json::parse(r->body)["served_quality"];
  }
  EXPECT_EQ(served, "standard") << server.log();
}

}  // namespace
}  // namespace clearsky::server
