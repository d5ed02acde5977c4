// GET /v1/irradiance/series over loopback with a real HTTP client: the JSON and CSV answers
// arrive chunked (streamed) and whole, local times across the autumn daylight saving change,
// night rows, the step cap (413 naming step) and planes refused naming planes, all in the
// server's one error format.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/server/http/server_fixture.h"

namespace clearsky::server {
namespace {

class IrradianceSeriesHttp : public testing::ServerFixture {};

const std::string kPlace = "/v1/irradiance/series?model=testsky&lat=48.85&lon=2.35";

TEST_F(IrradianceSeriesHttp, JsonAcrossTheAutumnChangeWithNightRows) {
  auto c = client();
  const auto r = c.Get(kPlace +
                       "&start=2024-10-27T00:00:00&end=2024-10-27T23:00:00&tz=Europe/Paris"
                       "&planes=30:180,90:90&ground_albedo=0.2");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(r->get_header_value("Transfer-Encoding"), "chunked");
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/json");
  const auto j = nlohmann::json::parse(r->body);
  // 24 hours between local midnight and 23:00 on the day with 25 hours: 25 rows.
  ASSERT_EQ(j["rows"].size(), 25u);
  EXPECT_EQ(j["rows"][2][1], "2024-10-27T02:00:00+02:00");
  EXPECT_EQ(j["rows"][3][1], "2024-10-27T02:00:00+01:00");
  EXPECT_EQ(j["sky_diffuse_on_planes"], "per_step");
  std::size_t nights = 0;
  for (const auto& row : j["rows"]) {
    if (!row[2].get<bool>()) continue;
    ++nights;
    // The test sky cannot go broadband: null broadband columns, zero model-range ones.
    for (std::size_t k = 5; k < row.size(); ++k) {
      const std::string name = j["columns"][k];
      if (name.rfind("model_range_", 0) == 0 || name.rfind("poa_illuminance", 0) == 0 ||
          name == "illuminance") {
        EXPECT_EQ(row[k].get<double>(), 0.0) << name;
      } else {
        EXPECT_TRUE(row[k].is_null()) << name;
      }
    }
  }
  EXPECT_GE(nights, 12u);
}

TEST_F(IrradianceSeriesHttp, CsvOneLinePerStep) {
  auto c = client();
  const auto r =
      c.Get(kPlace + "&start=2024-06-21T00:00:00Z&end=2024-06-22T00:00:00Z&step=PT10M&format=csv");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(r->get_header_value("Content-Type"), "text/csv");
  std::istringstream lines(r->body);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line,
            "time_utc,night,solar_zenith,solar_azimuth,ghi,dni,dhi,illuminance,model_range_ghi,"
            "model_range_dni,model_range_dhi");
  EXPECT_FALSE(r->get_header_value("Clearsky-Broadband-Unavailable").empty());
  std::size_t rows = 0;
  while (std::getline(lines, line)) ++rows;
  EXPECT_EQ(rows, 24u * 6 + 1);
}

TEST_F(IrradianceSeriesHttp, RefusalsNameTheParameter) {
  auto c = client();
  auto r = c.Get(kPlace + "&start=2024-01-01T00:00:00Z&end=2025-12-31T00:00:00Z&step=PT10M");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 413);
  EXPECT_EQ(nlohmann::json::parse(r->body)["error"]["parameter"], "step");
  r = c.Get(kPlace + "&start=2024-01-01T00:00:00Z&end=2024-01-02T00:00:00Z&planes=30;180");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_EQ(nlohmann::json::parse(r->body)["error"]["parameter"], "planes");
}

}  // namespace
}  // namespace clearsky::server
