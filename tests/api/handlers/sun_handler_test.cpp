// The sun query end to end without transport: the SPA report's example, polar night, and
// refusals naming the parameter (unknown ones included).
#include "api/handlers/sun_handler.h"

#include <gtest/gtest.h>

#include <cmath>

#include "api/error/api_error.h"

namespace clearsky::api {
namespace {

using Pairs = std::vector<std::pair<std::string, std::string>>;

nlohmann::ordered_json sun(const Pairs& pairs, double now_unix_s = 0.0) {
  Parameters p("GET /v1/sun");
  for (const auto& [name, value] : pairs) p.add(name, value);
  return handle_sun(p, now_unix_s);
}

TEST(SunHandler, ReportExampleAsJson) {
  const nlohmann::ordered_json answer = sun({{"lat", "39.742476"},
                                             {"lon", "-105.1786"},
                                             {"altitude", "1830.14"},
                                             {"time", "2003-10-17T12:30:30-07:00"},
                                             {"pressure", "820"},
                                             {"temperature", "11"},
                                             {"delta_t", "67"}});
  EXPECT_NEAR(answer.at("zenith").get<double>(), 50.11162, 1e-5);
  EXPECT_NEAR(answer.at("azimuth").get<double>(), 194.34024, 1e-5);
  EXPECT_EQ(answer.at("sunrise"), "2003-10-17T06:12:43-07:00");
  EXPECT_EQ(answer.at("transit"), "2003-10-17T11:46:05-07:00");
  EXPECT_EQ(answer.at("sunset").get<std::string>().substr(0, 17), "2003-10-17T17:18:");
  EXPECT_EQ(answer.at("day"), "normal");
}

// delta_t absent: Delta T of the time's year and month by the Espenak-Meeus expressions
// (models/solar/delta_t.h), reported with the answer; given: the request's value.
TEST(SunHandler, ReportsTheDeltaTItUsed) {
  const Pairs place{{"lat", "42.44"}, {"lon", "-76.48"}, {"time", "2020-01-10T12:00:00Z"}};
  const nlohmann::ordered_json computed = sun(place);
  // 2020 + 0.5 / 12: 62.92 + 0.32217 t + 0.005589 t^2 at t = 20.0417.
  EXPECT_NEAR(computed.at("delta_t_s").get<double>(), 71.6217, 1e-3);
  EXPECT_EQ(computed.at("delta_t_source"), "espenak_meeus");
  Pairs given = place;
  given.emplace_back("delta_t", "69.36");
  const nlohmann::ordered_json answer = sun(given);
  EXPECT_EQ(answer.at("delta_t_s").get<double>(), 69.36);
  EXPECT_EQ(answer.at("delta_t_source"), "given");
  // Delta T moves only the sun along its orbit (SPA's ephemeris is in TT; the Earth's rotation
  // is UT): 2.26 s at about 1.1e-5 degrees per second, about 2.6e-5 degrees.
  const double dz = computed.at("zenith").get<double>() - answer.at("zenith").get<double>();
  const double da = computed.at("azimuth").get<double>() - answer.at("azimuth").get<double>();
  EXPECT_GT(std::abs(dz) + std::abs(da), 1e-6);
  EXPECT_LT(std::abs(dz), 1e-4);
  EXPECT_LT(std::abs(da), 1e-4);
}

// After 3000 no expression is published: the request must give delta_t.
TEST(SunHandler, YearsWithoutDeltaTExpressionNeedDeltaT) {
  try {
    (void)sun({{"lat", "0"}, {"lon", "0"}, {"time", "3001-06-01T00:00:00Z"}});
    ADD_FAILURE();
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.parameter(), "delta_t");
  }
  EXPECT_EQ(sun({{"lat", "0"}, {"lon", "0"}, {"time", "3001-06-01T00:00:00Z"}, {"delta_t", "0"}})
                .at("delta_t_source"),
            "given");
}

TEST(SunHandler, PolarNightHasNullSunriseAndSunset) {
  const nlohmann::ordered_json answer =
      sun({{"lat", "-78.5"}, {"lon", "166.7"}, {"time", "2023-06-21T12:00:00+12:00"}});
  EXPECT_TRUE(answer.at("sunrise").is_null());
  EXPECT_TRUE(answer.at("sunset").is_null());
  EXPECT_TRUE(answer.at("transit").is_string());
  EXPECT_EQ(answer.at("day"), "polar_night");
  EXPECT_GT(answer.at("zenith").get<double>(), 90.0);
}

TEST(SunHandler, WithoutTimeTheGivenNowInUtc) {
  // 2013-05-27T15:45:00Z at the Kider site.
  const nlohmann::ordered_json answer = sun({{"lat", "42.44"}, {"lon", "-76.48"}}, 1369669500.0);
  EXPECT_NEAR(answer.at("zenith").get<double>(), 26.64, 0.02);
  EXPECT_EQ(answer.at("transit").get<std::string>().substr(0, 11), "2013-05-27T");
  EXPECT_EQ(answer.at("transit").get<std::string>().back(), 'Z');
}

TEST(SunHandler, InvalidParameterPropagates) {
  try {
    (void)sun({{"lat", "91"}, {"lon", "0"}});
    ADD_FAILURE();
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.parameter(), "lat");
  }
}

TEST(SunHandler, UnknownParametersAreNamed) {
  try {
    (void)sun({{"lat", "0"}, {"lon", "0"}, {"zenith", "3"}});
    ADD_FAILURE();
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.code(), "unknown_parameter");
    EXPECT_EQ(e.parameter(), "zenith");
  }
}

}  // namespace
}  // namespace clearsky::api
