// Per-sun states in the disk table cache against real `clearsky serve` processes
// (docs/tables-and-memory.md "Per-sun states"): a Haber dome computed by one server is loaded,
// not computed, by a second server started later on the same cache folder, and answers the same
// numbers. The server logs each per-sun preparation as computed or ready. A cheap 24-sector
// configuration keeps the computation short.
#include <gtest/gtest.h>
#include <httplib.h>

#include <chrono>
#include <string>
#include <thread>

#include "tests/server/http/serve_process.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

using testing::ServeProcess;

constexpr const char* kTarget =
    "/v1/radiance?model=haber&azimuth_sectors=24&sun_zenith=40&sun_azimuth=0&view_zenith=60&"
    "view_azimuth=10";

// The answer to kTarget once the server is ready (empty when it never was).
std::string answer(const ServeProcess& server) {
  httplib::Client c("127.0.0.1", server.port());
  c.set_read_timeout(120, 0);
  bool ready = false;
  for (int i = 0; i < 1200 && !ready; ++i) {
    const auto r = c.Get("/readyz");
    ready = r && r->status == 200;
    if (!ready) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (!ready) return {};
  const auto r = c.Get(kTarget);
  if (!r || r->status != 200) return {};
  return r->body;
}

TEST(SunStateDiskServe, ASecondServerLoadsTheSunStateTheFirstComputed) {
  clearsky::testing::TempDir dir;
  std::string first_answer;
  {
    ServeProcess first(dir.path, {"--build-wait-ms", "60000"}, "haber");
    ASSERT_GT(first.port(), 0) << first.log();
    first_answer = answer(first);
    ASSERT_FALSE(first_answer.empty()) << first.log();
    EXPECT_NE(first.log().find("sun state: haber sun zenith 40.0000 deg computed"),
              std::string::npos)
        << first.log();
  }
  ServeProcess second(dir.path, {"--build-wait-ms", "60000"}, "haber");
  ASSERT_GT(second.port(), 0) << second.log();
  EXPECT_EQ(answer(second), first_answer) << second.log();
  const std::string log = second.log();
  EXPECT_NE(log.find("sun state: haber sun zenith 40.0000 deg ready"), std::string::npos) << log;
  EXPECT_EQ(log.find(" deg computed"), std::string::npos) << log;
}

}  // namespace
}  // namespace clearsky::server
