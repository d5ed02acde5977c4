// GET /v1/skypatches with start (a sky matrix, api/skypatches/sky_patch_matrix.h) over loopback
// with a real HTTP client, on the analytic test sky: one column per step, night columns flagged
// and zero, each daytime column the sky vector GET /v1/skypatches answers for that instant, the
// CSV and Radiance encodings, and the refusals (413 naming step, radiance without start).
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/server/http/server_fixture.h"

namespace clearsky::server {
namespace {

class SkyMatrixHttp : public testing::ServerFixture {};

const std::string kDay =
    "/v1/skypatches?model=testsky&lat=48.85&lon=2.35&output=rgb&sun=patch"
    "&start=2024-06-21T00:00:00Z&end=2024-06-21T23:00:00Z&step=PT1H";

TEST_F(SkyMatrixHttp, OneColumnPerStepEachTheVectorOfItsInstant) {
  auto c = client();
  const auto r = c.Get(kDay + "&tz=Europe/Paris");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/json");
  const auto j = nlohmann::json::parse(r->body);
  ASSERT_EQ(j["steps"], 24);
  ASSERT_EQ(j["patch_count"], 146);
  ASSERT_EQ(j["matrix"].size(), 146u);
  ASSERT_EQ(j["matrix"][0].size(), 24u);
  ASSERT_EQ(j["times"].size(), 24u);
  EXPECT_EQ(j["times"][12]["time_local"], "2024-06-21T14:00:00+02:00");
  EXPECT_EQ(j["unanswered_steps"], 0);
  std::size_t nights = 0;
  for (std::size_t step = 0; step < 24; ++step) {
    const auto& time = j["times"][step];
    if (!time["night"].get<bool>()) continue;
    ++nights;
    EXPECT_EQ(time["sun_patch"], 0);
    for (std::size_t patch = 0; patch < 146; ++patch)
      EXPECT_EQ(j["matrix"][patch][step], nlohmann::json({0.0, 0.0, 0.0}));
  }
  EXPECT_GE(nights, 6u);
  EXPECT_LE(nights, 10u);
  // 12:00Z: the column is the single vector of that instant (floats in the matrix).
  const auto one = c.Get(
      "/v1/skypatches?model=testsky&lat=48.85&lon=2.35&output=rgb&sun=patch"
      "&time=2024-06-21T12:00:00Z");
  ASSERT_TRUE(one);
  ASSERT_EQ(one->status, 200) << one->body;
  const auto vector = nlohmann::json::parse(one->body);
  EXPECT_EQ(j["times"][12]["sun_patch"], vector["sun_patch"]);
  EXPECT_NEAR(j["times"][12]["sun_zenith_deg"].get<double>(),
              vector["sun"]["zenith_deg"].get<double>(), 1e-9);
  for (std::size_t patch = 0; patch < 146; ++patch) {
    for (std::size_t c3 = 0; c3 < 3; ++c3) {
      const double expected = vector["patches"][patch]["value"][c3].get<double>();
      EXPECT_NEAR(j["matrix"][patch][12][c3].get<double>(), expected, 1e-6 * expected + 1e-12)
          << "patch " << patch;
    }
  }
}

TEST_F(SkyMatrixHttp, CsvAndRadianceMatrices) {
  auto c = client();
  auto r = c.Get(kDay + "&format=csv");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(r->get_header_value("Content-Type"), "text/csv");
  std::istringstream lines(r->body);
  std::string header, night, line;
  std::getline(lines, header);
  std::getline(lines, night);
  EXPECT_EQ(header.rfind("patch,altitude_deg,azimuth_deg,solid_angle_sr,2024-06-21T00:00:00Z_R,"
                         "2024-06-21T00:00:00Z_G,2024-06-21T00:00:00Z_B,2024-06-21T01:00:00Z_R",
                         0),
            0u)
      << header;
  EXPECT_EQ(std::count(header.begin(), header.end(), ','), 3 + 24 * 3);
  EXPECT_EQ(night.rfind("night,,,,1,1,1,", 0), 0u) << night;
  std::size_t rows = 0;
  while (std::getline(lines, line)) {
    EXPECT_EQ(line.rfind(std::to_string(rows) + ",", 0), 0u);
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 3 + 24 * 3);
    ++rows;
  }
  EXPECT_EQ(rows, 146u);

  r = c.Get(kDay + "&format=radiance");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(r->body.rfind("#?RADIANCE\nNROWS=146\nNCOLS=24\nNCOMP=3\nFORMAT=ascii\n\n", 0), 0u);
  std::istringstream values(r->body.substr(r->body.find("\n\n") + 2));
  std::size_t numbers = 0;
  double x = 0;
  while (values >> x) {
    EXPECT_GE(x, 0.0);
    ++numbers;
  }
  EXPECT_EQ(numbers, 146u * 24 * 3);
}

TEST_F(SkyMatrixHttp, RefusalsNameTheParameter) {
  auto c = client();
  // A year hourly in Reinhart MF 2 RGB: 8784 x 578 x 3 values, above the cap.
  auto r = c.Get(
      "/v1/skypatches?model=testsky&lat=48.85&lon=2.35&output=rgb&scheme=reinhart&mf=2"
      "&start=2024-01-01T00:00:00Z&end=2024-12-31T23:00:00Z");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 413);
  EXPECT_EQ(nlohmann::json::parse(r->body)["error"]["parameter"], "step");
  r = c.Get("/v1/skypatches?model=testsky&sun_zenith=30&sun_azimuth=180&format=radiance");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_EQ(nlohmann::json::parse(r->body)["error"]["parameter"], "format");
  r = c.Get(kDay + "&time=2024-06-21T12:00:00Z");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_EQ(nlohmann::json::parse(r->body)["error"]["parameter"], "time");
}

}  // namespace
}  // namespace clearsky::server
