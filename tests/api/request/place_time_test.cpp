// ISO 8601 times with offsets, coordinates in decimal and DMS, and SPA through the request.
#include "api/request/place_time.h"

#include <gtest/gtest.h>

#include "api/error/api_error.h"

namespace clearsky::api {
namespace {

TEST(PlaceTime, ParsesOffsetsAndZulu) {
  // 2013-05-27T15:45:00Z is 1369669500 s after the epoch.
  EXPECT_DOUBLE_EQ(parse_iso_time("time", "2013-05-27T15:45:00Z").unix_time_utc_s, 1369669500.0);
  const IsoTime edt = parse_iso_time("time", "2013-05-27T11:45:00-04:00");
  EXPECT_DOUBLE_EQ(edt.unix_time_utc_s, 1369669500.0);
  EXPECT_DOUBLE_EQ(edt.offset_h, -4.0);
  EXPECT_DOUBLE_EQ(parse_iso_time("time", "2013-05-27T21:15+0530").unix_time_utc_s, 1369669500.0);
  EXPECT_DOUBLE_EQ(parse_iso_time("time", "2013-05-27T15:45:00.25Z").unix_time_utc_s,
                   1369669500.25);
  EXPECT_DOUBLE_EQ(parse_iso_time("time", "1970-01-01T00:00:00Z").unix_time_utc_s, 0.0);
  EXPECT_DOUBLE_EQ(parse_iso_time("time", "2000-02-29T00:00:00Z").unix_time_utc_s, 951782400.0);
}

TEST(PlaceTime, RejectsMalformedTimes) {
  for (const char* bad :
       {"2013-05-27T11:45:00", "2013-05-27", "2013-13-01T00:00Z", "2013-02-29T00:00Z",
        "2013-05-27T24:00Z", "2013-05-27T11:45:00-04:00x", "yesterday", "2013-5-27T11:45Z"}) {
    try {
      parse_iso_time("time", bad);
      ADD_FAILURE() << bad;
    } catch (const ApiError& e) {
      EXPECT_EQ(e.status(), 400) << bad;
      EXPECT_EQ(e.parameter(), "time") << bad;
    }
  }
}

TEST(PlaceTime, FormatsInTheGivenOffset) {
  EXPECT_EQ(format_iso_time(1369669500.0, -4.0), "2013-05-27T11:45:00-04:00");
  EXPECT_EQ(format_iso_time(1369669500.0, 0.0), "2013-05-27T15:45:00Z");
  EXPECT_EQ(format_iso_time(951782400.0, 5.5), "2000-02-29T05:30:00+05:30");
}

TEST(PlaceTime, DecodesDmsAndChecksHemispheres) {
  Parameters p("GET /v1/sun");
  p.add("lat", "42d26'36\"N");
  p.add("lon", "76d28'55\"W");
  p.add("time", "2013-05-27T11:45:00-04:00");
  const PlaceAndTime place = parse_place_and_time(p);
  EXPECT_NEAR(place.spa_input.latitude_deg, 42.0 + 26.0 / 60 + 36.0 / 3600, 1e-12);
  EXPECT_NEAR(place.spa_input.longitude_deg, -(76.0 + 28.0 / 60 + 55.0 / 3600), 1e-12);
  Parameters q("GET /v1/sun");
  q.add("lat", "42E");
  q.add("lon", "0");
  q.add("time", "2013-05-27T11:45:00-04:00");
  try {
    parse_place_and_time(q);
    ADD_FAILURE();
  } catch (const ApiError& e) {
    EXPECT_EQ(e.parameter(), "lat");
  }
}

}  // namespace
}  // namespace clearsky::api
