// ISO 8601 date-time of a request, in the extended format with a UTC offset or Z:
//   YYYY-MM-DDThh:mm[:ss[.fff]](Z|+hh:mm|-hh:mm|+hhmm|-hhmm|+hh|-hh)
// e.g. "2013-05-27T11:45:00-04:00", "2003-10-17T19:30:30.25Z". A time without an offset is
// rejected (a local time names no instant) unless its time zone is given apart, as an IANA
// zone name (parse_iso8601_local_time). Years 0000-9999 of the proleptic Gregorian calendar;
// no leap seconds (unix time has none); offsets up to 14 hours (the widest in use, UTC+14 in
// Kiribati). Calendar and time zones are Howard Hinnant's date/tz (Debian
// libhowardhinnant-date-dev), which reads the system's IANA time zone database
// (/usr/share/zoneinfo, Debian package tzdata). Errors are api::ApiError (400 invalid_parameter) naming the
// parameter.
#pragma once

#include <string>
#include <string_view>

namespace clearsky::api {

struct Iso8601Time {
  double unix_time_utc_s = 0;   // the instant, seconds since 1970-01-01T00:00:00Z
  int utc_offset_min = 0;       // local time minus UTC, minutes
  bool utc_designator = false;  // written with "Z" (so answers use "Z" too)
};

Iso8601Time parse_iso8601_time(std::string_view text, const std::string& parameter = "time");

// A UTC offset alone, as it ends a time above: Z, +hh:mm, +hhmm or +hh (and with '-'), at most
// 14 hours; the offset in minutes (local time minus UTC, e.g. -240 for "-04:00").
int parse_utc_offset_minutes(std::string_view text, const std::string& parameter = "utc_offset");

// A local time without offset, YYYY-MM-DDThh:mm[:ss[.fff]], in the IANA time zone `zone`
// (e.g. "Europe/Paris"): the instant, with the zone's UTC offset at that instant (daylight
// saving time included). A local time that the zone skips (the hour lost when clocks go
// forward) is refused naming `parameter`; one it repeats (clocks going back) is the earlier
// instant. An unknown zone is refused naming `zone_parameter`.
Iso8601Time parse_iso8601_local_time(std::string_view text, std::string_view zone,
                                     const std::string& parameter = "time",
                                     const std::string& zone_parameter = "tz");

}  // namespace clearsky::api
