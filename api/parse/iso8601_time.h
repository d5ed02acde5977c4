// ISO 8601 date-time of a request, in the extended format with a UTC offset or Z:
//   YYYY-MM-DDThh:mm[:ss[.fff]](Z|+hh:mm|-hh:mm|+hhmm|-hhmm|+hh|-hh)
// e.g. "2013-05-27T11:45:00-04:00", "2003-10-17T19:30:30.25Z". A time without an offset is
// rejected (a local time names no instant). Years 0000-9999 of the proleptic Gregorian
// calendar; no leap seconds (unix time has none); offsets up to 18 hours. Errors are
// api::InvalidParameter naming the parameter.
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

}  // namespace clearsky::api
