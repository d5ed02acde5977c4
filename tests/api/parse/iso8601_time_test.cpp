// ISO 8601 time parsing: offsets, Z, fractions, and rejection of malformed or impossible times.
#include "api/parse/iso8601_time.h"

#include <gtest/gtest.h>

#include "api/parse/invalid_parameter.h"

namespace clearsky::api {
namespace {

TEST(ParseIso8601Time, OffsetsAndZ) {
  // 2013-05-27T11:45:00-04:00 = 15:45:00Z (the Kider capture at 11:45 EDT).
  Iso8601Time t = parse_iso8601_time("2013-05-27T11:45:00-04:00");
  EXPECT_DOUBLE_EQ(t.unix_time_utc_s, 1369669500.0);
  EXPECT_EQ(t.utc_offset_min, -240);
  EXPECT_FALSE(t.utc_designator);

  t = parse_iso8601_time("2003-10-17T19:30:30Z");
  EXPECT_DOUBLE_EQ(t.unix_time_utc_s, 1066419030.0);
  EXPECT_EQ(t.utc_offset_min, 0);
  EXPECT_TRUE(t.utc_designator);

  EXPECT_DOUBLE_EQ(parse_iso8601_time("2003-10-17T12:30:30-07:00").unix_time_utc_s, 1066419030.0);
  EXPECT_DOUBLE_EQ(parse_iso8601_time("2003-10-17T12:30:30-0700").unix_time_utc_s, 1066419030.0);
  EXPECT_DOUBLE_EQ(parse_iso8601_time("2003-10-18T01:00:30+05:30").unix_time_utc_s, 1066419030.0);
  EXPECT_EQ(parse_iso8601_time("2003-10-18T01:00:30+05:30").utc_offset_min, 330);
  EXPECT_DOUBLE_EQ(parse_iso8601_time("2003-10-18T04:30:30+09").unix_time_utc_s, 1066419030.0);
  EXPECT_DOUBLE_EQ(parse_iso8601_time("1970-01-01T00:00Z").unix_time_utc_s, 0.0);
}

TEST(ParseIso8601Time, FractionalSecondsAndCalendarEdges) {
  EXPECT_DOUBLE_EQ(parse_iso8601_time("1970-01-01T00:00:00.25Z").unix_time_utc_s, 0.25);
  EXPECT_DOUBLE_EQ(parse_iso8601_time("1969-12-31T23:59:59,5Z").unix_time_utc_s, -0.5);
  EXPECT_DOUBLE_EQ(parse_iso8601_time("2000-02-29T12:00:00Z").unix_time_utc_s, 951825600.0);
  EXPECT_DOUBLE_EQ(parse_iso8601_time("2000-01-01T12:00:00Z").unix_time_utc_s, 946728000.0);
  EXPECT_DOUBLE_EQ(parse_iso8601_time("0000-01-01T00:00:00Z").unix_time_utc_s, -62167219200.0);
}

TEST(ParseIso8601Time, MalformedOrImpossibleTimesAreRejected) {
  for (const char* bad : {"",
                          "2013-05-27",
                          "2013-05-27T11:45:00",
                          "2013-05-27 11:45:00Z",
                          "13-05-27T11:45:00Z",
                          "2013-5-27T11:45:00Z",
                          "2013-05-27T11:45:00+4",
                          "2013-05-27T11:45:00-04:",
                          "2013-05-27T11:45:00.Z",
                          "2013-13-01T00:00:00Z",
                          "2013-02-29T00:00:00Z",
                          "2013-04-31T00:00:00Z",
                          "2013-05-27T24:00:00Z",
                          "2013-05-27T11:60:00Z",
                          "2013-05-27T11:45:60Z",
                          "2013-05-27T11:45:00+19:00",
                          "2013-05-27T11:45:00-04:60",
                          "2013-05-27T11:45:00Zjunk",
                          "2013-05-27T11:45:00 Z",
                          "2013-05-27T11:45:00-04:00 ",
                          "nan",
                          "+2013-05-27T11:45:00Z"}) {
    try {
      (void)parse_iso8601_time(bad, "time");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InvalidParameter& e) {
      EXPECT_EQ(e.parameter(), "time");
      EXPECT_NE(std::string(e.what()).find("2013-05-27T11:45:00-04:00"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace clearsky::api
