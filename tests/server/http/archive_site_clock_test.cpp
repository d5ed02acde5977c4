// The site and clock of a Kider archive upload (docs/measurement-formats.md, api/datasets/
// import_site_clock.h) against `clearsky serve` and its database: given, they are stored with
// the capture and give its sun; absent, the published captures' Cornell site and UTC-04:00;
// out of range, a 400 naming the parameter before anything is recorded.
#include <gtest/gtest.h>
#include <httplib.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "models/evaluation/capture_preparation.h"
#include "tests/server/durability/background_work_client.h"
#include "tests/server/http/hostile_clients.h"
#include "tests/server/http/serve_process.h"
#include "tests/support/synthetic_kider_zip.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

nlohmann::json json_of(const httplib::Result& r) { return nlohmann::json::parse(r->body); }

// Uploads the archive with the query; the finished import.
nlohmann::json imported(httplib::Client& c, const std::string& bytes, const std::string& query) {
  const auto accepted = c.Post(("/v1/datasets?" + query).c_str(), bytes, "application/zip");
  EXPECT_TRUE(accepted);
  if (!accepted) return {};
  EXPECT_EQ(accepted->status, 202) << accepted->body;
  return testing::await_end(c, accepted->get_header_value("Location"), std::chrono::seconds(300));
}

TEST(ArchiveSiteClock, AnUploadIsStoredAtTheSiteAndClockGiven) {
  clearsky::testing::TempDir dir;
  testing::ServeProcess serve(dir.path, {"--token", testing::kDurabilityToken});
  ASSERT_TRUE(testing::ready(serve.port(), std::chrono::seconds(120))) << serve.log();
  httplib::Client c = testing::token_client(serve);
  clearsky::testing::write_synthetic_kider_zip(dir.path / "capture.zip");
  std::ifstream in(dir.path / "capture.zip", std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();

  ASSERT_EQ(
      imported(c, bytes.str(),
               "name=paris&lat=48.8566&lon=2.3522&elevation=35&utc_offset=%2B02:00")["status"],
      "succeeded");
  const nlohmann::json paris = json_of(c.Get("/v1/datasets/paris"))["captures"][0];
  EXPECT_EQ(paris["time"], "2013-05-27T12:00:00+02:00");
  EXPECT_EQ(paris["time_utc"], "2013-05-27T10:00:00Z");
  EXPECT_EQ(
      paris["place"],
      nlohmann::json::parse(R"({"latitude": 48.8566, "longitude": 2.3522, "elevation_m": 35.0})"));
  MeasuredCapture expected;
  expected.site = {48.8566, 2.3522, 35};
  expected.unix_time_utc_s = 1369648800.0;  // 2013-05-27T10:00:00Z
  compute_sun_position(expected);
  EXPECT_DOUBLE_EQ(paris["sun_zenith"].get<double>(), expected.sun_zenith_computed_deg);
  EXPECT_DOUBLE_EQ(paris["sun_azimuth"].get<double>(), expected.sun_azimuth_computed_deg);

  // Without them: the published captures' site and clock, as before.
  ASSERT_EQ(imported(c, bytes.str(), "name=cornell")["status"], "succeeded");
  const nlohmann::json cornell = json_of(c.Get("/v1/datasets/cornell"))["captures"][0];
  EXPECT_EQ(cornell["time"], "2013-05-27T12:00:00-04:00");
  EXPECT_EQ(cornell["place"]["latitude"], 42.443449);
  EXPECT_EQ(cornell["place"]["elevation_m"], 250.0);

  // Out of range: refused naming the parameter, nothing recorded.
  for (const auto& [query, parameter] :
       std::vector<std::pair<std::string, std::string>>{{"lat=91", "lat"},
                                                        {"lon=200", "lon"},
                                                        {"elevation=20000", "elevation"},
                                                        {"utc_offset=%2B15:00", "utc_offset"},
                                                        {"utc_offset=4", "utc_offset"}}) {
    const auto r =
        c.Post(("/v1/datasets?name=x&" + query).c_str(), bytes.str(), "application/octet-stream");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400) << query << ": " << r->body;
    EXPECT_EQ(json_of(r)["error"]["parameter"], parameter) << r->body;
  }
  EXPECT_EQ(json_of(c.Get("/v1/imports")).size(), 2u);
}

}  // namespace
}  // namespace clearsky::server
