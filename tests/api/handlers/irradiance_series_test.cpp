// GET /v1/irradiance/series (api/irradiance/irradiance_series.h) on the analytic test sky:
// rows, columns, night rows, local times across a daylight saving change, the ground on a
// vertical plane, CSV, and the refusals (step cap, planes, step, end before start).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

#include "api/handlers/handlers.h"
#include "api/irradiance/plane_list.h"
#include "api/parse/iso8601_duration.h"
#include "tests/support/synchronous_provider.h"
#include "tests/support/test_sky_model.h"

namespace clearsky::api {
namespace {

using Q = std::vector<std::pair<std::string, std::string>>;

class IrradianceSeries : public ::testing::Test {
 protected:
  // The status and the whole streamed body (or the error's).
  std::pair<int, std::string> call(Q extra) {
    Q q{{"model", "testsky"}, {"lat", "45"}, {"lon", "5"}};
    q.insert(q.end(), extra.begin(), extra.end());
    ApiRequest r{"GET", "/v1/irradiance/series", std::move(q), ""};
    const ApiContext context{provider, limits};
    try {
      const ApiResponse response = irradiance_series(context, r);
      std::string body;
      const bool complete = response.stream([&](const char* data, std::size_t size) {
        body.append(data, size);
        return true;
      });
      EXPECT_TRUE(complete);
      return {response.status, body};
    } catch (const ApiError& e) {
      const ApiResponse response = error_response(e);
      return {response.status, response.body};
    }
  }
  static std::string parameter_of(const std::string& body) {
    return nlohmann::json::parse(body)["error"]["parameter"].get<std::string>();
  }
  static std::size_t column(const nlohmann::json& j, const std::string& name) {
    const auto& columns = j["columns"];
    for (std::size_t i = 0; i < columns.size(); ++i)
      if (columns[i] == name) return i;
    ADD_FAILURE() << "no column " << name;
    return 0;
  }

  clearsky::testing::SynchronousProvider provider{clearsky::testing::test_factories()};
  Limits limits{100, 500, 1024};
};

TEST_F(IrradianceSeries, OneRowPerStepWithNightRowsAndPlanes) {
  const auto [status, body] = call({{"start", "2024-06-21T00:00:00Z"},
                                    {"end", "2024-06-21T23:00:00Z"},
                                    {"planes", "30:180,90:180"},
                                    {"ground_albedo", "0.3"}});
  ASSERT_EQ(status, 200) << body;
  const auto j = nlohmann::json::parse(body);
  ASSERT_EQ(j["rows"].size(), 24u);
  EXPECT_EQ(j["steps"], 24);
  EXPECT_EQ(j["unanswered_steps"], 0);
  EXPECT_EQ(j["columns"].size(), 11u + 2 * 11);
  // The analytic sky cannot go broadband: its own figures are the model_range_* columns.
  const std::size_t night = column(j, "night"), ghi = column(j, "model_range_ghi"),
                    ground = column(j, "model_range_poa_ground_diffuse_90_180"),
                    global = column(j, "model_range_poa_global_30_180"),
                    direct = column(j, "model_range_poa_direct_30_180"),
                    diffuse = column(j, "model_range_poa_diffuse_30_180"),
                    sky = column(j, "model_range_poa_sky_diffuse_30_180"),
                    ground30 = column(j, "model_range_poa_ground_diffuse_30_180");
  std::size_t nights = 0;
  for (const auto& row : j["rows"]) {
    if (row[night].get<bool>()) {
      ++nights;
      EXPECT_EQ(row[ghi].get<double>(), 0.0);
      EXPECT_EQ(row[global].get<double>(), 0.0);
      continue;
    }
    EXPECT_GT(row[ghi].get<double>(), 0.0);
    // The isotropic ground on a vertical plane: albedo x GHI / 2.
    EXPECT_NEAR(row[ground].get<double>(), 0.3 * row[ghi].get<double>() / 2, 1e-9);
    EXPECT_NEAR(row[global].get<double>(), row[direct].get<double>() + row[diffuse].get<double>(),
                1e-9);
    EXPECT_NEAR(row[diffuse].get<double>(), row[sky].get<double>() + row[ground30].get<double>(),
                1e-9);
  }
  // At 45 N, 5 E on the June solstice the sun is down from about 19:40 to 04:00 UTC.
  EXPECT_GE(nights, 6u);
  EXPECT_LE(nights, 10u);
  EXPECT_EQ(j["rows"][0][0], "2024-06-21T00:00:00Z");
  EXPECT_EQ(j["rows"][23][0], "2024-06-21T23:00:00Z");
}

TEST_F(IrradianceSeries, LocalTimesAcrossTheSpringDaylightSavingChange) {
  const auto [status, body] = call({{"start", "2024-03-31T00:00:00"},
                                    {"end", "2024-03-31T04:00:00"},
                                    {"tz", "Europe/Paris"},
                                    {"step", "PT1H"}});
  ASSERT_EQ(status, 200) << body;
  const auto j = nlohmann::json::parse(body);
  // 00:00 CET is 23:00Z, 04:00 CEST is 02:00Z: four hours, the local 02:00 skipped.
  ASSERT_EQ(j["rows"].size(), 4u);
  const std::size_t local = column(j, "time_local");
  EXPECT_EQ(j["rows"][0][0], "2024-03-30T23:00:00Z");
  EXPECT_EQ(j["rows"][0][local], "2024-03-31T00:00:00+01:00");
  EXPECT_EQ(j["rows"][1][local], "2024-03-31T01:00:00+01:00");
  EXPECT_EQ(j["rows"][2][local], "2024-03-31T03:00:00+02:00");
  EXPECT_EQ(j["rows"][3][local], "2024-03-31T04:00:00+02:00");
  for (const auto& row : j["rows"]) EXPECT_TRUE(row[column(j, "night")].get<bool>());
}

TEST_F(IrradianceSeries, CsvHasTheColumnsAndOneLinePerStep) {
  const auto [status, body] = call({{"start", "2024-06-21T10:00:00Z"},
                                    {"end", "2024-06-21T12:00:00Z"},
                                    {"step", "PT30M"},
                                    {"planes", "90:90"},
                                    {"format", "csv"}});
  ASSERT_EQ(status, 200) << body;
  std::istringstream lines(body);
  std::string header, line;
  std::getline(lines, header);
  EXPECT_EQ(header,
            "time_utc,night,solar_zenith,solar_azimuth,ghi,dni,dhi,illuminance,model_range_ghi,"
            "model_range_dni,model_range_dhi,poa_global_90_90,poa_direct_90_90,poa_diffuse_90_90,"
            "poa_sky_diffuse_90_90,poa_ground_diffuse_90_90,poa_illuminance_90_90,"
            "model_range_poa_global_90_90,model_range_poa_direct_90_90,"
            "model_range_poa_diffuse_90_90,model_range_poa_sky_diffuse_90_90,"
            "model_range_poa_ground_diffuse_90_90");
  std::size_t rows = 0;
  while (std::getline(lines, line)) {
    ++rows;
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 21) << line;
    EXPECT_NE(line.find(",false,"), std::string::npos) << line;
  }
  EXPECT_EQ(rows, 5u);
}

TEST_F(IrradianceSeries, Refusals) {
  // A year every minute is above the cap: 413 naming step.
  auto [status, body] =
      call({{"start", "2024-01-01T00:00:00Z"}, {"end", "2024-12-31T23:00:00Z"}, {"step", "PT1M"}});
  EXPECT_EQ(status, 413) << body;
  EXPECT_EQ(parameter_of(body), "step");
  const Q day{{"start", "2024-06-21T00:00:00Z"}, {"end", "2024-06-21T02:00:00Z"}};
  for (const char* planes : {"30", "30:abc", "200:180", "30:180,,90:90", "30:180,30:180", ""}) {
    Q q = day;
    q.emplace_back("planes", planes);
    std::tie(status, body) = call(q);
    EXPECT_EQ(status, 400) << planes;
    EXPECT_EQ(parameter_of(body), "planes") << planes;
  }
  for (const char* step : {"1H", "PT", "P1H", "PT-1H", "PT0S", "PT1.5H", "P1M"}) {
    Q q = day;
    q.emplace_back("step", step);
    std::tie(status, body) = call(q);
    EXPECT_EQ(status, 400) << step;
    EXPECT_EQ(parameter_of(body), "step") << step;
  }
  std::tie(status, body) =
      call({{"start", "2024-06-21T02:00:00Z"}, {"end", "2024-06-21T00:00:00Z"}});
  EXPECT_EQ(status, 400);
  EXPECT_EQ(parameter_of(body), "end");
  std::tie(status, body) = call(
      {{"start", "2024-03-31T02:30:00"}, {"end", "2024-03-31T04:00:00"}, {"tz", "Europe/Paris"}});
  EXPECT_EQ(status, 400);
  EXPECT_EQ(parameter_of(body), "start");
  std::tie(status, body) =
      call({{"start", "2024-03-31T02:30:00Z"}, {"end", "2024-03-31T04:00:00Z"}, {"tz", "Mars/X"}});
  EXPECT_EQ(status, 400);
  EXPECT_EQ(parameter_of(body), "tz");
  Q with_time = day;
  with_time.emplace_back("time", "2024-06-21T00:00:00Z");
  std::tie(status, body) = call(with_time);
  EXPECT_EQ(status, 400);
  EXPECT_EQ(parameter_of(body), "time");
}

TEST(Iso8601Duration, Seconds) {
  EXPECT_EQ(parse_iso8601_duration_s("PT1H", "step"), 3600);
  EXPECT_EQ(parse_iso8601_duration_s("PT10M", "step"), 600);
  EXPECT_EQ(parse_iso8601_duration_s("PT1H30M", "step"), 5400);
  EXPECT_EQ(parse_iso8601_duration_s("P1DT12H", "step"), 129600);
  EXPECT_EQ(parse_iso8601_duration_s("PT45S", "step"), 45);
}

TEST(PlaneList, SuffixesAsWritten) {
  const auto planes = parse_planes("30:180,90:-90,22.5:180");
  ASSERT_EQ(planes.size(), 3u);
  EXPECT_EQ(planes[0].suffix, "_30_180");
  EXPECT_EQ(planes[1].suffix, "_90_-90");
  EXPECT_EQ(planes[2].tilt_deg, 22.5);
}

}  // namespace
}  // namespace clearsky::api
