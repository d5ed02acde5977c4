// ISO 8601 time parsing: offsets, Z, fractions, rejection of malformed or impossible times, and
// local times in IANA time zones (the system's tz database).
#include "api/parse/iso8601_time.h"

#include <gtest/gtest.h>

#include "api/error/api_error.h"

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
                          "2013-05-27T11:45:00+14:01",
                          "2013-05-27T11:45:00-1401",
                          "2013-05-27T11:45:00+15",
                          "2013-05-27T11:45:00-04:60",
                          "2013-05-27T11:45:00Zjunk",
                          "2013-05-27T11:45:00 Z",
                          "2013-05-27T11:45:00-04:00 ",
                          "nan",
                          "+2013-05-27T11:45:00Z"}) {
    try {
      (void)parse_iso8601_time(bad, "time");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const ApiError& e) {
      EXPECT_EQ(e.parameter(), "time");
      EXPECT_NE(std::string(e.what()).find("2013-05-27T11:45:00-04:00"), std::string::npos)
          << e.what();
    }
  }
}

TEST(ParseIso8601Time, OffsetsUpTo14HoursAreAccepted) {
  EXPECT_EQ(parse_iso8601_time("2013-05-27T11:45:00+14:00").utc_offset_min, 840);
  EXPECT_EQ(parse_iso8601_time("2013-05-27T11:45:00-14:00").utc_offset_min, -840);
  EXPECT_EQ(parse_iso8601_time("2013-05-27T11:45:00-1345").utc_offset_min, -825);
}

TEST(ParseIso8601LocalTime, EuropeParisWithAndWithoutDaylightSavingTime) {
  // Summer: CEST, UTC+2.
  Iso8601Time t = parse_iso8601_local_time("2024-07-01T14:00:00", "Europe/Paris");
  EXPECT_DOUBLE_EQ(t.unix_time_utc_s, 1719835200.0);
  EXPECT_EQ(t.utc_offset_min, 120);
  EXPECT_FALSE(t.utc_designator);
  // Winter: CET, UTC+1; fractions and a time without seconds as in parse_iso8601_time.
  t = parse_iso8601_local_time("2024-01-15T12:00:00.5", "Europe/Paris");
  EXPECT_DOUBLE_EQ(t.unix_time_utc_s, 1705316400.5);
  EXPECT_EQ(t.utc_offset_min, 60);
  EXPECT_DOUBLE_EQ(parse_iso8601_local_time("2024-01-15T12:00", "Europe/Paris").unix_time_utc_s,
                   1705316400.0);
  // The Kider capture at 11:45 EDT.
  t = parse_iso8601_local_time("2013-05-27T11:45:00", "America/New_York");
  EXPECT_DOUBLE_EQ(t.unix_time_utc_s, 1369669500.0);
  EXPECT_EQ(t.utc_offset_min, -240);
}

TEST(ParseIso8601LocalTime, RepeatedLocalTimesAreTheEarlierInstant) {
  // 2024-10-27 in Paris: 03:00 CEST goes back to 02:00 CET, 02:30 happens twice.
  const Iso8601Time t = parse_iso8601_local_time("2024-10-27T02:30:00", "Europe/Paris");
  EXPECT_DOUBLE_EQ(t.unix_time_utc_s, 1729989000.0);  // 00:30Z, at UTC+2
  EXPECT_EQ(t.utc_offset_min, 120);
  EXPECT_DOUBLE_EQ(parse_iso8601_local_time("2024-10-27T03:30:00", "Europe/Paris").unix_time_utc_s,
                   1729992600.0 + 3600.0);  // 02:30Z, at UTC+1
}

TEST(ParseIso8601LocalTime, SkippedTimesUnknownZonesAndOffsetsAreRefused) {
  const auto refused_naming = [](const char* text, const char* zone) -> std::string {
    try {
      (void)parse_iso8601_local_time(text, zone, "time", "tz");
    } catch (const ApiError& e) {
      return e.parameter();
    }
    return "accepted";
  };
  // 2024-03-31 in Paris: 02:00 CET goes forward to 03:00 CEST, 02:30 does not exist.
  EXPECT_EQ(refused_naming("2024-03-31T02:30:00", "Europe/Paris"), "time");
  EXPECT_EQ(refused_naming("2024-03-31T01:59:59", "Europe/Paris"), "accepted");
  EXPECT_EQ(refused_naming("2024-07-01T14:00:00", "Mars/Olympus_Mons"), "tz");
  EXPECT_EQ(refused_naming("2024-07-01T14:00:00", ""), "tz");
  EXPECT_EQ(refused_naming("2024-07-01T14:00:00", "../../../etc/passwd"), "tz");
  EXPECT_EQ(refused_naming("2024-07-01T14:00:00+02:00", "Europe/Paris"), "time");
  EXPECT_EQ(refused_naming("2024-07-01T14:00:00Z", "Europe/Paris"), "time");
  EXPECT_EQ(refused_naming("2024-02-30T14:00:00", "Europe/Paris"), "time");
}

}  // namespace
}  // namespace clearsky::api
