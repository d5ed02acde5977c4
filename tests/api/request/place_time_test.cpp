// Place and time of sky requests: ISO 8601 with offset, decimal and DMS coordinates, the sun
// through SPA, and errors naming the parameter.
#include "api/request/place_time.h"

#include <gtest/gtest.h>

#include "api/error/api_error.h"

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
    EXPECT_DOUBLE_EQ(parse_place_and_time(p).unix_time_utc_s, 1369669500.0) << t;
  }
}

TEST(PlaceTime, RejectsMalformedTimesNamingTime) {
  for (const char* bad :
       {"2013-05-27T11:45:00", "2013-13-01T00:00Z", "2013-02-29T00:00Z", "yesterday"}) {
    Parameters p = place("42", "-76", bad);
    try {
      parse_place_and_time(p);
      ADD_FAILURE() << bad;
    } catch (const ApiError& e) {
      EXPECT_EQ(e.status(), 400) << bad;
      EXPECT_EQ(e.parameter(), "time") << bad;
    }
  }
}

TEST(PlaceTime, DecodesDmsAndChecksHemispheres) {
  Parameters p = place("42d26'36\"N", "76d28'55\"W", "2013-05-27T11:45:00-04:00");
  const SolarPositionInput in = parse_place_and_time(p);
  EXPECT_NEAR(in.latitude_deg, 42.0 + 26.0 / 60 + 36.0 / 3600, 1e-12);
  EXPECT_NEAR(in.longitude_deg, -(76.0 + 28.0 / 60 + 55.0 / 3600), 1e-12);
  Parameters q = place("42E", "0", "2013-05-27T11:45:00-04:00");
  try {
    parse_place_and_time(q);
    ADD_FAILURE();
  } catch (const ApiError& e) {
    EXPECT_EQ(e.parameter(), "lat");
  }
}

TEST(PlaceTime, SunThroughSpa) {
  Parameters p = place("42.44", "-76.48", "2013-05-27T11:45:00-04:00");
  const SolarPosition s = solar_position_checked(parse_place_and_time(p));
  EXPECT_NEAR(s.zenith_deg, 26.64, 0.02);
  EXPECT_NEAR(s.azimuth_deg, 136.07, 0.02);
}

}  // namespace
}  // namespace clearsky::api
