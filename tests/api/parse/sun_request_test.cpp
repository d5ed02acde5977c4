// The sun request from text parameters: defaults, DMS and ISO input, and errors naming the
// parameter (including those SPA's own validation finds).
#include "api/parse/sun_request.h"

#include <gtest/gtest.h>

#include "api/parse/invalid_parameter.h"

namespace clearsky::api {
namespace {

std::string rejected(const QueryParameters& parameters) {
  try {
    (void)parse_sun_request(parameters, 0.0);
  } catch (const InvalidParameter& e) {
    return e.parameter();
  }
  return "";
}

TEST(ParseSunRequest, FullRequest) {
  const SunRequest r = parse_sun_request({{"lat", "39.742476"},
                                          {"lon", "-105.1786"},
                                          {"altitude", "1830.14"},
                                          {"time", "2003-10-17T12:30:30-07:00"},
                                          {"pressure", "820"},
                                          {"temperature", "11"},
                                          {"delta_t", "67"},
                                          {"delta_ut1", "0"},
                                          {"refraction", "false"}},
                                         0.0);
  EXPECT_DOUBLE_EQ(r.position.latitude_deg, 39.742476);
  EXPECT_DOUBLE_EQ(r.position.longitude_deg, -105.1786);
  EXPECT_DOUBLE_EQ(r.position.elevation_m, 1830.14);
  EXPECT_DOUBLE_EQ(r.position.unix_time_utc_s, 1066419030.0);
  EXPECT_DOUBLE_EQ(r.position.pressure_mbar, 820.0);
  EXPECT_DOUBLE_EQ(r.position.temperature_c, 11.0);
  EXPECT_DOUBLE_EQ(r.position.delta_t_s, 67.0);
  EXPECT_FALSE(r.position.refraction);
  EXPECT_EQ(r.utc_offset_min, -420);
  EXPECT_FALSE(r.utc_designator);
}

TEST(ParseSunRequest, DefaultsAndDms) {
  const SunRequest r =
      parse_sun_request({{"lat", "42d26'36.4\"N"}, {"lon", "76d28'55.1\"W"}}, 1369669500.0);
  EXPECT_NEAR(r.position.latitude_deg, 42.44344, 1e-5);
  EXPECT_NEAR(r.position.longitude_deg, -76.48197, 1e-5);
  EXPECT_DOUBLE_EQ(r.position.unix_time_utc_s, 1369669500.0);
  EXPECT_TRUE(r.utc_designator);
  EXPECT_DOUBLE_EQ(r.position.elevation_m, 0.0);
  EXPECT_DOUBLE_EQ(r.position.pressure_mbar, 1013.25);
  EXPECT_TRUE(r.position.refraction);
}

TEST(ParseSunRequest, ErrorsNameTheParameter) {
  EXPECT_EQ(rejected({{"lon", "0"}}), "lat");
  EXPECT_EQ(rejected({{"lat", "0"}}), "lon");
  EXPECT_EQ(rejected({{"lat", "nan"}, {"lon", "0"}}), "lat");
  EXPECT_EQ(rejected({{"lat", "91"}, {"lon", "0"}}), "lat");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lat", "1"}, {"lon", "0"}}), "lat");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"zenith", "3"}}), "zenith");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"time", "2013-05-27T11:45:00"}}), "time");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"time", "7000-01-01T00:00:00Z"}}), "time");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"pressure", "6000"}}), "pressure");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"pressure", "nan"}}), "pressure");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"temperature", "-300"}}), "temperature");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"altitude", "-7000000"}}), "altitude");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"delta_t", "9000"}}), "delta_t");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"delta_ut1", "1"}}), "delta_ut1");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"refraction", "maybe"}}), "refraction");
  try {
    (void)parse_sun_request({{"lat", "0"}, {"lon", "0"}, {"pressure", "6000"}}, 0.0);
  } catch (const InvalidParameter& e) {
    EXPECT_STREQ(e.what(), "pressure: must be in [0, 5000] mbar, got 6000");
  }
}

}  // namespace
}  // namespace clearsky::api
