// The per-client build rate against a real `clearsky serve` (requests from 127.0.0.1): each new
// atmosphere configuration of an anonymous GET builds tables; beyond --build-rate builds per
// --build-rate-window-s the client gets 429 + Retry-After naming build_rate, while requests
// that build nothing are still answered.
#include <gtest/gtest.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "tests/server/http/watched_serve_process.h"

namespace clearsky::server {
namespace {

using testing::WatchedServeProcess;

std::string radiance_target(const std::string& atmosphere) {
  return "/v1/"
         "radiance?model=preetham&sun_zenith=40&sun_azimuth=100&view_zenith=60&view_azimuth=10" +
         atmosphere;
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(BuildRateServe, AClientBeyondItsBuildsPerWindowGets429NamingBuildRate) {
  WatchedServeProcess server({"--models", "preetham", "--prebuild-three", "false", "--build-rate",
                              "2", "--build-rate-window-s", "3600", "--build-wait-ms", "60000"});
  ASSERT_GT(server.port(), 0) << server.log();
  auto c = server.client(90);
  bool ready = false;
  for (int i = 0; i < 1200 && !ready; ++i) {
    const auto r = c.Get("/readyz");
    ready = r && r->status == 200;
    if (!ready) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_TRUE(ready) << server.log();

  // Two new configurations: two builds, answered.
  for (const char* turbidity : {"&turbidity=3", "&turbidity=4"}) {
    const auto r = c.Get(radiance_target(turbidity));
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << r->body;
  }
  // The third new configuration is refused before anything is built.
  const auto refused = c.Get(radiance_target("&turbidity=5"));
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 429) << refused->body;
  ASSERT_TRUE(refused->has_header("Retry-After"));
  const int retry_after_s = std::stoi(refused->get_header_value("Retry-After"));
  EXPECT_GT(retry_after_s, 0);
  EXPECT_LE(retry_after_s, 3600);
  const auto error = nlohmann::json::parse(refused->body)["error"];
  EXPECT_EQ(error["code"], "too_many_builds");
  EXPECT_EQ(error["parameter"], "build_rate");
  EXPECT_NE(error["message"].get<std::string>().find("127.0.0.1"), std::string::npos);
  // Built: the default at start and the two configurations; nothing for the refused one.
  EXPECT_EQ(occurrences(server.log(), "tables: building preetham"), 3u) << server.log();

  // What builds nothing is still answered: the default, and a configuration already built.
  for (const char* atmosphere : {"", "&turbidity=3"}) {
    const auto r = c.Get(radiance_target(atmosphere));
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << r->body;
  }
  EXPECT_TRUE(server.alive());
}

}  // namespace
}  // namespace clearsky::server
