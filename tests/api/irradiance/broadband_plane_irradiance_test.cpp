// The one broadband step (api/irradiance/broadband_plane_irradiance.h) behind GET
// /v1/irradiance and GET /v1/irradiance/series: the series' ghi, dni, dhi and poa_* of Bruneton
// (small tables, as the pyranometer test) are /v1/irradiance's broadband figures at the same
// place and instants, the model_range_* columns its model-range ones; a model that cannot go
// broadband has null broadband columns and says why, in JSON and in CSV.
#include "api/irradiance/broadband_plane_irradiance.h"

#include <gtest/gtest.h>

#include <sstream>
#include <tuple>

#include "api/handlers/handlers.h"
#include "models/registry.h"
#include "tests/support/synchronous_provider.h"
#include "tests/support/test_sky_model.h"

namespace clearsky::api {
namespace {

using Q = std::vector<std::pair<std::string, std::string>>;

const Q kSmallBruneton = {{"model", "bruneton"},    {"lat", "42.443449"},
                          {"lon", "-76.481962"},    {"altitude", "250"},
                          {"table_r_size", "8"},    {"table_mu_size", "32"},
                          {"table_mu_s_size", "8"}, {"table_nu_size", "4"},
                          {"ground_albedo", "0.2"}, {"precipitable_water_cm", "2"}};

std::string streamed_body(const ApiResponse& r) {
  std::string body;
  r.stream([&](const char* data, std::size_t size) {
    body.append(data, size);
    return true;
  });
  return body;
}

double at(const nlohmann::json& series, std::size_t row, const std::string& column) {
  const auto& columns = series["columns"];
  for (std::size_t k = 0; k < columns.size(); ++k)
    if (columns[k] == column) return series["rows"][row][k].get<double>();
  ADD_FAILURE() << "no column " << column;
  return 0.0;
}

TEST(BroadbandPlaneIrradiance, SeriesColumnsAreTheIrradianceEndpointsFigures) {
  const auto factories = registered_models();
  clearsky::testing::SynchronousProvider provider{{factories.begin(), factories.end()}};
  const Limits limits{100, 500, 1024};
  const ApiContext context{provider, limits};
  Q q = kSmallBruneton;
  q.insert(q.end(), {{"start", "2013-05-27T09:30:00-04:00"},
                     {"end", "2013-05-27T15:30:00-04:00"},
                     {"step", "PT3H"},
                     {"planes", "30:180,90:90"}});
  const auto series =
      nlohmann::json::parse(streamed_body(irradiance_series(context, {"GET", "", q, ""})));
  ASSERT_EQ(series["rows"].size(), 3u);
  EXPECT_EQ(series["broadband"]["precipitable_water_cm"], 2.0);
  EXPECT_FALSE(series.contains("broadband_unavailable"));
  const char* times[] = {"2013-05-27T09:30:00-04:00", "2013-05-27T12:30:00-04:00",
                         "2013-05-27T15:30:00-04:00"};
  for (std::size_t row = 0; row < 3; ++row) {
    const auto irradiance_at = [&](const char* tilt, const char* azimuth) {
      Q one = kSmallBruneton;
      one.insert(one.end(), {{"time", times[row]}, {"tilt", tilt}, {"surface_azimuth", azimuth}});
      return nlohmann::json::parse(irradiance(context, {"GET", "", one, ""}).body);
    };
    const auto horizontal = irradiance_at("0", "180");
    const auto bb = [](const nlohmann::json& c) {
      return c["broadband_irradiance_w_m2"].get<double>();
    };
    EXPECT_DOUBLE_EQ(at(series, row, "ghi"), bb(horizontal["global"])) << times[row];
    EXPECT_DOUBLE_EQ(at(series, row, "dni"), bb(horizontal["direct_normal"]));
    EXPECT_DOUBLE_EQ(at(series, row, "dhi"), bb(horizontal["diffuse"]));
    EXPECT_DOUBLE_EQ(at(series, row, "model_range_ghi"),
                     horizontal["global"]["model_range_irradiance_w_m2"].get<double>());
    // The broadband figures are the whole solar spectrum: well above the model's range.
    EXPECT_GT(at(series, row, "ghi"), 1.3 * at(series, row, "model_range_ghi"));
    for (const auto& [tilt, azimuth, suffix] :
         {std::tuple{"30", "180", "_30_180"}, std::tuple{"90", "90", "_90_90"}}) {
      const auto plane = irradiance_at(tilt, azimuth);
      const std::string s = suffix;
      EXPECT_DOUBLE_EQ(at(series, row, "poa_global" + s), bb(plane["global"])) << s;
      EXPECT_DOUBLE_EQ(at(series, row, "poa_direct" + s), bb(plane["direct"])) << s;
      EXPECT_DOUBLE_EQ(at(series, row, "poa_sky_diffuse" + s), bb(plane["diffuse"])) << s;
      EXPECT_DOUBLE_EQ(at(series, row, "poa_ground_diffuse" + s), bb(plane["ground_diffuse"]));
      EXPECT_NEAR(at(series, row, "poa_diffuse" + s),
                  bb(plane["diffuse"]) + bb(plane["ground_diffuse"]), 1e-9);
      EXPECT_DOUBLE_EQ(at(series, row, "model_range_poa_global" + s),
                       plane["global"]["model_range_irradiance_w_m2"].get<double>());
      // On a vertical plane the ground term is albedo x GHI / 2, broadband too.
      if (s == "_90_90") {
        EXPECT_NEAR(at(series, row, "poa_ground_diffuse" + s), 0.2 * at(series, row, "ghi") / 2,
                    1e-9);
      }
    }
  }
}

TEST(BroadbandPlaneIrradiance, AModelThatCannotGoBroadbandSaysSoInJsonAndCsv) {
  clearsky::testing::SynchronousProvider provider{clearsky::testing::test_factories()};
  const Limits limits{100, 500, 1024};
  const ApiContext context{provider, limits};
  Q q = {{"model", "testsky"},
         {"lat", "45"},
         {"lon", "5"},
         {"start", "2024-06-21T00:00:00Z"},
         {"end", "2024-06-21T12:00:00Z"},
         {"planes", "30:180"}};
  const auto j =
      nlohmann::json::parse(streamed_body(irradiance_series(context, {"GET", "", q, ""})));
  EXPECT_TRUE(j["broadband"].is_null());
  EXPECT_NE(j["broadband_unavailable"].get<std::string>().find("testsky"), std::string::npos);
  const auto& columns = j["columns"];
  for (const auto& row : j["rows"]) {
    const bool night = row[1].get<bool>();
    for (std::size_t k = 0; k < columns.size(); ++k) {
      const std::string name = columns[k];
      const bool broadband = name == "ghi" || name == "dni" || name == "dhi" ||
                             (name.rfind("poa_", 0) == 0 && name.rfind("poa_illuminance", 0) != 0);
      if (broadband) {
        EXPECT_TRUE(row[k].is_null()) << name;  // never a smaller number under the name
      } else if (name == "model_range_ghi") {
        EXPECT_TRUE(night ? row[k] == 0.0 : row[k].get<double>() > 0.0) << name;
      }
    }
  }
  q.emplace_back("format", "csv");
  const ApiResponse csv = irradiance_series(context, {"GET", "", q, ""});
  bool said = false;
  for (const auto& [name, value] : csv.headers)
    said |= name == "Clearsky-Broadband-Unavailable" && value == j["broadband_unavailable"];
  EXPECT_TRUE(said);
  std::istringstream lines(streamed_body(csv));
  std::string header, line, noon;
  std::getline(lines, header);
  while (std::getline(lines, line)) noon = line;
  // 2024-06-21T12:00:00Z: ghi, dni and dhi empty, the model's own figures given.
  EXPECT_EQ(header.substr(0, header.find(",model_range_poa")),
            "time_utc,night,solar_zenith,solar_azimuth,ghi,dni,dhi,illuminance,model_range_ghi,"
            "model_range_dni,model_range_dhi,poa_global_30_180,poa_direct_30_180,"
            "poa_diffuse_30_180,poa_sky_diffuse_30_180,poa_ground_diffuse_30_180,"
            "poa_illuminance_30_180");
  EXPECT_NE(noon.find(",false,"), std::string::npos) << noon;
  EXPECT_NE(noon.find(",,,"), std::string::npos) << noon;
}

}  // namespace
}  // namespace clearsky::api
