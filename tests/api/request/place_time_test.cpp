// Place and time of every request: ISO 8601 with offset, decimal and DMS coordinates, the
// table's defaults and ranges, the sun through SPA, and errors naming the parameter (those SPA
// itself finds included).
#include "api/request/place_time.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "api/error/api_error.h"
#include "tests/support/place_time_cases.h"

namespace clearsky::api {
namespace {

Parameters place(const std::string& lat, const std::string& lon, const std::string& time) {
  Parameters p("GET /v1/radiance");
  p.add("lat", lat);
  p.add("lon", lon);
  p.add("time", time);
  return p;
}

TEST(PlaceTime, ParsesTimesWithOffsets) {
  // 2013-05-27T15:45:00Z is 1369669500 s after the epoch.
  for (const char* t :
       {"2013-05-27T15:45:00Z", "2013-05-27T11:45:00-04:00", "2013-05-27T21:15+05:30"}) {
    Parameters p = place("42", "-76", t);
    EXPECT_DOUBLE_EQ(parse_place_and_time(p, std::nullopt).position.unix_time_utc_s, 1369669500.0)
        << t;
  }
}

TEST(PlaceTime, RejectsMalformedTimesNamingTime) {
  for (const char* bad :
       {"2013-05-27T11:45:00", "2013-13-01T00:00Z", "2013-02-29T00:00Z", "yesterday"}) {
    Parameters p = place("42", "-76", bad);
    try {
      parse_place_and_time(p, std::nullopt);
      ADD_FAILURE() << bad;
    } catch (const ApiError& e) {
      EXPECT_EQ(e.status(), 400) << bad;
      EXPECT_EQ(e.parameter(), "time") << bad;
    }
  }
}

TEST(PlaceTime, DecodesDmsAndChecksHemispheres) {
  Parameters p = place("42d26'36\"N", "76d28'55\"W", "2013-05-27T11:45:00-04:00");
  const SolarPositionInput in = parse_place_and_time(p, std::nullopt).position;
  EXPECT_NEAR(in.latitude_deg, 42.0 + 26.0 / 60 + 36.0 / 3600, 1e-12);
  EXPECT_NEAR(in.longitude_deg, -(76.0 + 28.0 / 60 + 55.0 / 3600), 1e-12);
  Parameters q = place("42E", "0", "2013-05-27T11:45:00-04:00");
  try {
    parse_place_and_time(q, std::nullopt);
    ADD_FAILURE();
  } catch (const ApiError& e) {
    EXPECT_EQ(e.parameter(), "lat");
  }
}

TEST(PlaceTime, SunThroughSpa) {
  Parameters p = place("42.44", "-76.48", "2013-05-27T11:45:00-04:00");
  const SolarPosition s = solar_position_checked(parse_place_and_time(p, std::nullopt).position);
  EXPECT_NEAR(s.zenith_deg, 26.64, 0.02);
  EXPECT_NEAR(s.azimuth_deg, 136.07, 0.02);
}

using Pairs = std::vector<std::pair<std::string, std::string>>;

// The parameter named by the refusal of these parameters, "" when they are accepted.
std::string rejected(const Pairs& pairs) {
  try {
    Parameters p("GET /v1/sun");
    for (const auto& [name, value] : pairs) p.add(name, value);
    (void)parse_place_and_time(p, 0.0);
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 400) << e.what();
    return e.parameter();
  }
  return "";
}

TEST(PlaceTime, FullRequest) {
  Parameters p("GET /v1/sun");
  for (const auto& [name, value] : Pairs{{"lat", "39.742476"},
                                         {"lon", "-105.1786"},
                                         {"altitude", "1830.14"},
                                         {"time", "2003-10-17T12:30:30-07:00"},
                                         {"pressure", "820"},
                                         {"temperature", "11"},
                                         {"delta_t", "67"},
                                         {"delta_ut1", "0.25"},
                                         {"refraction", "false"}})
    p.add(name, value);
  const PlaceTime r = parse_place_and_time(p, 0.0);
  EXPECT_NO_THROW(p.reject_unused());
  EXPECT_DOUBLE_EQ(r.position.latitude_deg, 39.742476);
  EXPECT_DOUBLE_EQ(r.position.longitude_deg, -105.1786);
  EXPECT_DOUBLE_EQ(r.position.elevation_m, 1830.14);
  EXPECT_DOUBLE_EQ(r.position.unix_time_utc_s, 1066419030.0);
  EXPECT_DOUBLE_EQ(r.position.pressure_mbar, 820.0);
  EXPECT_DOUBLE_EQ(r.position.temperature_c, 11.0);
  EXPECT_DOUBLE_EQ(r.position.delta_t_s, 67.0);
  EXPECT_DOUBLE_EQ(r.position.delta_ut1_s, 0.25);
  EXPECT_FALSE(r.position.refraction);
  EXPECT_EQ(r.utc_offset_min, -420);
  EXPECT_FALSE(r.utc_designator);
}

TEST(PlaceTime, DefaultsAreTheTablesAndTimeDefaultsToNow) {
  Parameters p("GET /v1/sun");
  p.add("lat", "42d26'36.4\"N");
  p.add("lon", "76d28'55.1\"W");
  const PlaceTime r = parse_place_and_time(p, 1369669500.0);
  EXPECT_NEAR(r.position.latitude_deg, 42.44344, 1e-5);
  EXPECT_NEAR(r.position.longitude_deg, -76.48197, 1e-5);
  EXPECT_DOUBLE_EQ(r.position.unix_time_utc_s, 1369669500.0);
  EXPECT_TRUE(r.utc_designator);
  EXPECT_EQ(r.utc_offset_min, 0);
  EXPECT_DOUBLE_EQ(r.position.elevation_m, 0.0);
  EXPECT_DOUBLE_EQ(r.position.pressure_mbar, 1013.25);
  EXPECT_DOUBLE_EQ(r.position.temperature_c, 15.0);
  // 2013-05 by the Espenak-Meeus expressions (models/solar/delta_t.h), not a fixed value.
  EXPECT_NEAR(r.position.delta_t_s, 68.2288, 1e-4);
  EXPECT_TRUE(r.delta_t_from_time);
  EXPECT_DOUBLE_EQ(r.position.delta_ut1_s, 0.0);
  EXPECT_TRUE(r.position.refraction);
}

TEST(PlaceTime, WithoutNowTimeIsRequired) {
  Parameters p("GET /v1/radiance");
  p.add("lat", "42");
  p.add("lon", "-76");
  try {
    (void)parse_place_and_time(p, std::nullopt);
    ADD_FAILURE();
  } catch (const ApiError& e) {
    EXPECT_EQ(e.code(), "missing_parameter");
    EXPECT_EQ(e.parameter(), "time");
  }
}

TEST(PlaceTime, ErrorsNameTheParameter) {
  EXPECT_EQ(rejected({{"lon", "0"}}), "lat");
  EXPECT_EQ(rejected({{"lat", "0"}}), "lon");
  EXPECT_EQ(rejected({{"lat", "nan"}, {"lon", "0"}}), "lat");
  EXPECT_EQ(rejected({{"lat", "91"}, {"lon", "0"}}), "lat");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lat", "1"}, {"lon", "0"}}), "lat");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"time", "2013-05-27T11:45:00"}}), "time");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"time", "7000-01-01T00:00:00Z"}}), "time");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"pressure", "6000"}}), "pressure");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"pressure", "nan"}}), "pressure");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"temperature", "-300"}}), "temperature");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"altitude", "-7000000"}}), "altitude");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"delta_t", "9000"}}), "delta_t");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"delta_ut1", "1"}}), "delta_ut1");
  EXPECT_EQ(rejected({{"lat", "0"}, {"lon", "0"}, {"refraction", "maybe"}}), "refraction");
  Parameters p("GET /v1/sun");
  p.add("lat", "0");
  p.add("lon", "0");
  p.add("pressure", "6000");
  try {
    (void)parse_place_and_time(p, 0.0);
    ADD_FAILURE();
  } catch (const ApiError& e) {
    EXPECT_STREQ(e.what(), "pressure: must be in [0, 5000] mbar, got 6000");
    EXPECT_EQ(e.reason(), "must be in [0, 5000] mbar, got 6000");
  }
}

// Every limit of the table, at and beyond it.
TEST(PlaceTime, EveryLimitOfTheTable) {
  for (const auto& c : clearsky::testing::place_time_cases()) {
    // delta_t given: the years after 3000 have no computed default (models/solar/delta_t.h).
    Pairs pairs{{"lat", "10"}, {"lon", "20"}, {"delta_t", "69"}};
    std::erase_if(pairs, [&](const auto& pair) { return pair.first == c.parameter; });
    pairs.emplace_back(c.parameter, c.value);
    EXPECT_EQ(rejected(pairs), c.accepted ? "" : c.parameter) << c.parameter << "=" << c.value;
  }
}

// Out-of-range inputs that only SPA's own validation sees (the API checks first) still come
// back naming the request parameter: one per field of SolarPositionInput.
TEST(PlaceTime, SpaRefusalsNameTheRequestParameter) {
  struct Case {
    const char* parameter;
    void (*spoil)(SolarPositionInput&);
  };
  const Case cases[] = {
      {"time", [](SolarPositionInput& in) { in.unix_time_utc_s = 158000000000.0; }},  // 7000
      {"lat", [](SolarPositionInput& in) { in.latitude_deg = 91.0; }},
      {"lon", [](SolarPositionInput& in) { in.longitude_deg = -181.0; }},
      {"altitude", [](SolarPositionInput& in) { in.elevation_m = -7e6; }},
      {"pressure", [](SolarPositionInput& in) { in.pressure_mbar = 6000.0; }},
      {"temperature", [](SolarPositionInput& in) { in.temperature_c = -273.0; }},
      {"delta_t", [](SolarPositionInput& in) { in.delta_t_s = 9000.0; }},
      {"delta_ut1", [](SolarPositionInput& in) { in.delta_ut1_s = 1.0; }},
  };
  for (const Case& c : cases) {
    SolarPositionInput in;
    in.unix_time_utc_s = 1369669500.0;
    c.spoil(in);
    try {
      (void)solar_position_checked(in);
      ADD_FAILURE() << c.parameter;
    } catch (const ApiError& e) {
      EXPECT_EQ(e.status(), 400) << e.what();
      EXPECT_EQ(e.parameter(), c.parameter) << e.what();
    }
    EXPECT_TRUE(std::ranges::any_of(place_time_parameters(), [&](const auto& row) {
      return row.name == c.parameter;
    })) << c.parameter;
  }
}

}  // namespace
}  // namespace clearsky::api
