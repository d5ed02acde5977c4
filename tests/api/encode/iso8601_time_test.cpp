// ISO 8601 formatting of instants at an offset or in an IANA time zone, and the round trip
// through the parser.
#include "api/encode/iso8601_time.h"

#include <gtest/gtest.h>

#include <cmath>

#include "api/parse/iso8601_time.h"

namespace clearsky::api {
namespace {

TEST(FormatIso8601Time, OffsetsZAndRounding) {
  EXPECT_EQ(format_iso8601_time(1066419030.0, -420), "2003-10-17T12:30:30-07:00");
  EXPECT_EQ(format_iso8601_time(1066419030.0, 0, true), "2003-10-17T19:30:30Z");
  EXPECT_EQ(format_iso8601_time(1066419030.0, 0), "2003-10-17T19:30:30+00:00");
  EXPECT_EQ(format_iso8601_time(1066419030.0, 330), "2003-10-18T01:00:30+05:30");
  EXPECT_EQ(format_iso8601_time(1066419030.0, -150), "2003-10-17T17:00:30-02:30");
  EXPECT_EQ(format_iso8601_time(1066419029.6, -420), "2003-10-17T12:30:30-07:00");
  EXPECT_EQ(format_iso8601_time(-0.4, 0, true), "1970-01-01T00:00:00Z");
  EXPECT_EQ(format_iso8601_time(-1.0, 0, true), "1969-12-31T23:59:59Z");
  EXPECT_EQ(format_iso8601_time(-62167219200.0 - 86400.0, 0, true), "-0001-12-31T00:00:00Z");
}

TEST(FormatIso8601Time, RoundTripsThroughTheParser) {
  for (const char* text : {"2013-05-27T11:45:00-04:00", "2000-02-29T23:59:59+14:00",
                           "1900-03-01T00:00:00Z", "0001-01-01T06:07:08-12:00"}) {
    const Iso8601Time t = parse_iso8601_time(text);
    EXPECT_EQ(format_iso8601_time(t.unix_time_utc_s, t.utc_offset_min, t.utc_designator), text);
  }
}

TEST(FormatIso8601Time, RejectsNonFiniteInstants) {
  EXPECT_THROW((void)format_iso8601_time(std::nan(""), 0), std::invalid_argument);
  EXPECT_THROW((void)format_iso8601_time(0.0, 19 * 60), std::invalid_argument);
  EXPECT_THROW((void)format_iso8601_time(0.0, 14 * 60 + 1), std::invalid_argument);
  EXPECT_THROW((void)format_iso8601_time(1e13, 0), std::invalid_argument);
}

TEST(FormatIso8601Time, ExpandedYears) {
  // 10000-01-01T00:00:00Z.
  EXPECT_EQ(format_iso8601_time(253402300800.0, 0, true), "+10000-01-01T00:00:00Z");
  EXPECT_EQ(format_iso8601_time(253402300799.0, 0, true), "9999-12-31T23:59:59Z");
}

TEST(FormatIso8601TimeInZone, OffsetsFollowDaylightSavingTime) {
  EXPECT_EQ(utc_offset_min_in_zone(1719835200.0, "Europe/Paris"), 120);
  EXPECT_EQ(utc_offset_min_in_zone(1705316400.0, "Europe/Paris"), 60);
  EXPECT_EQ(utc_offset_min_in_zone(1369669500.0, "America/New_York"), -240);
  EXPECT_EQ(utc_offset_min_in_zone(1369669500.0, "UTC"), 0);
  EXPECT_EQ(format_iso8601_time_in_zone(1719835200.0, "Europe/Paris"), "2024-07-01T14:00:00+02:00");
  EXPECT_EQ(format_iso8601_time_in_zone(1705316400.0, "Europe/Paris"), "2024-01-15T12:00:00+01:00");
  // The hour before and after clocks go back in Paris (2024-10-27 01:00Z).
  EXPECT_EQ(format_iso8601_time_in_zone(1729990800.0 - 1.0, "Europe/Paris"),
            "2024-10-27T02:59:59+02:00");
  EXPECT_EQ(format_iso8601_time_in_zone(1729990800.0 + 1800.0, "Europe/Paris"),
            "2024-10-27T02:30:00+01:00");
  EXPECT_THROW((void)utc_offset_min_in_zone(0.0, "Mars/Olympus_Mons"), std::invalid_argument);
}

TEST(FormatIso8601TimeInZone, RoundTripsThroughTheLocalTimeParser) {
  for (double unix_s : {1719835200.0, 1705316400.0, 1729989000.0, 1711846800.0 - 1.0}) {
    const std::string text = format_iso8601_time_in_zone(unix_s, "Europe/Paris");
    const std::string local = text.substr(0, text.size() - 6);  // without the offset
    const Iso8601Time t = parse_iso8601_local_time(local, "Europe/Paris");
    EXPECT_DOUBLE_EQ(t.unix_time_utc_s, unix_s) << text;
    EXPECT_EQ(format_iso8601_time(t.unix_time_utc_s, t.utc_offset_min), text);
  }
}

}  // namespace
}  // namespace clearsky::api
