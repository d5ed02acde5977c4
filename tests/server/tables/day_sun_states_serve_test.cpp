// The background pass over the day's per-sun states (server/tables/day_sun_states.h,
// docs/tables-and-memory.md "The day's per-sun states") against real `clearsky serve`
// processes: /readyz reports the buckets built out of the total; once the pass is done, a sun no
// request asked for is answered from the states the pass left (the server's log says "ready",
// not "computed": counted, not timed); a second server on the same cache folder finds every
// bucket in the disk cache and computes none. Nishita96's draft (2-degree buckets, 17 nodes)
// keeps the pass short.
#include <gtest/gtest.h>
#include <httplib.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "tests/server/http/serve_process.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

using testing::ServeProcess;

// /readyz's day_sun_states of nishita96 once the pass has built every bucket (null when it never
// did within the deadline: generous, the pass runs at the lowest priority on a loaded machine).
nlohmann::json finished_pass(const ServeProcess& server) {
  httplib::Client c("127.0.0.1", server.port());
  c.set_read_timeout(60, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(900);
  while (std::chrono::steady_clock::now() < deadline) {
    const auto r = c.Get("/readyz");
    if (r && r->status == 200) {
      const auto body = nlohmann::json::parse(r->body);
      const auto& pass = body["models"]["nishita96"]["day_sun_states"];
      if (pass.is_object() && pass["built"] == pass["total"]) return pass;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  return nullptr;
}

// The server's log once it holds `text` (or at the deadline). The pass writes its summary line
// after /readyz counts its last bucket, and it runs at the lowest priority: on a loaded machine
// the line can come seconds after finished_pass() returned.
std::string log_once_it_has(const ServeProcess& server, const std::string& text) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
  std::string log = server.log();
  while (log.find(text) == std::string::npos && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    log = server.log();
  }
  return log;
}

TEST(DaySunStatesServe, AfterThePassANewSunIsAnsweredWithoutABuild) {
  clearsky::testing::TempDir dir;
  const std::vector<std::string> options = {"--build-wait-ms", "60000", "--prebuild",
                                            "nishita96:draft"};
  {
    ServeProcess server(dir.path, options, "nishita96");
    ASSERT_GT(server.port(), 0) << server.log();
    const nlohmann::json pass = finished_pass(server);
    ASSERT_TRUE(pass.is_object()) << server.log();
    // Zenith 0 to the dark threshold of 111 degrees in 2-degree buckets.
    EXPECT_GE(pass["total"].get<int>(), 56) << pass;
    EXPECT_LE(pass["total"].get<int>(), 57) << pass;

    httplib::Client c("127.0.0.1", server.port());
    c.set_read_timeout(120, 0);
    const auto r = c.Get(
        "/v1/radiance?model=nishita96&quality=draft&sun_zenith=51.3&sun_azimuth=77&"
        "view_zenith=60&view_azimuth=10");
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    const std::string log = server.log();
    EXPECT_NE(log.find("sun state: nishita96 sun zenith 51.3000 deg ready"), std::string::npos)
        << log;
    EXPECT_EQ(log.find(" deg computed"), std::string::npos) << log;

    // The same check sees a computation: a bucket width the pass did not cover.
    const auto other = c.Get(
        "/v1/radiance?model=nishita96&quality=draft&sun_zenith_bucket_deg=1.5&sun_zenith=51.3&"
        "sun_azimuth=77&view_zenith=60&view_azimuth=10");
    ASSERT_TRUE(other);
    ASSERT_EQ(other->status, 200) << other->body;
    EXPECT_NE(server.log().find("sun state: nishita96 sun zenith 51.3000 deg computed"),
              std::string::npos)
        << server.log();
  }
  // A server started later on the same cache folder: every bucket is loaded, none computed.
  ServeProcess second(dir.path, options, "nishita96");
  ASSERT_GT(second.port(), 0) << second.log();
  ASSERT_TRUE(finished_pass(second).is_object()) << second.log();
  const std::string log = log_once_it_has(second, "day sun states: nishita96");
  EXPECT_NE(log.find("day sun states: nishita96"), std::string::npos) << log;
  EXPECT_NE(log.find("(0 computed"), std::string::npos) << log;
}

}  // namespace
}  // namespace clearsky::server
