// ISO 8601 formatting of instants at an offset, and the round trip through the parser.
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
}

}  // namespace
}  // namespace clearsky::api
