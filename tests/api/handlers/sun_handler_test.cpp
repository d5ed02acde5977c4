// The sun query end to end without transport: the SPA report's example and polar night.
#include "api/handlers/sun_handler.h"

#include <gtest/gtest.h>

#include "api/parse/invalid_parameter.h"

namespace clearsky::api {
namespace {

TEST(SunHandler, ReportExampleAsJson) {
  const nlohmann::ordered_json answer = handle_sun({{"lat", "39.742476"},
                                                    {"lon", "-105.1786"},
                                                    {"altitude", "1830.14"},
                                                    {"time", "2003-10-17T12:30:30-07:00"},
                                                    {"pressure", "820"},
                                                    {"temperature", "11"},
                                                    {"delta_t", "67"}},
                                                   0.0);
  EXPECT_NEAR(answer.at("zenith").get<double>(), 50.11162, 1e-5);
  EXPECT_NEAR(answer.at("azimuth").get<double>(), 194.34024, 1e-5);
  EXPECT_EQ(answer.at("sunrise"), "2003-10-17T06:12:43-07:00");
  EXPECT_EQ(answer.at("transit"), "2003-10-17T11:46:05-07:00");
  EXPECT_EQ(answer.at("sunset").get<std::string>().substr(0, 17), "2003-10-17T17:18:");
  EXPECT_EQ(answer.at("day"), "normal");
}

TEST(SunHandler, PolarNightHasNullSunriseAndSunset) {
  const nlohmann::ordered_json answer =
      handle_sun({{"lat", "-78.5"}, {"lon", "166.7"}, {"time", "2023-06-21T12:00:00+12:00"}}, 0.0);
  EXPECT_TRUE(answer.at("sunrise").is_null());
  EXPECT_TRUE(answer.at("sunset").is_null());
  EXPECT_TRUE(answer.at("transit").is_string());
  EXPECT_EQ(answer.at("day"), "polar_night");
  EXPECT_GT(answer.at("zenith").get<double>(), 90.0);
}

TEST(SunHandler, InvalidParameterPropagates) {
  EXPECT_THROW((void)handle_sun({{"lat", "91"}, {"lon", "0"}}, 0.0), InvalidParameter);
}

}  // namespace
}  // namespace clearsky::api
