// ISO 8601 text of an instant at a UTC offset, to the nearest second:
// "2003-10-17T06:12:43-07:00", or "...Z" when asked for the UTC designator (the form that
// api/parse/iso8601_time.h reads back); or at the offset of an IANA time zone at that instant
// (date/tz over the system's tz database, as the parser).
#pragma once

#include <string>
#include <string_view>

namespace clearsky::api {

// utc_offset_min in [-840, 840] (UTC-14:00 to UTC+14:00); unix_time_utc_s finite and within
// 9e11 s of 1970 (years before 0000 or after 9999 are written with a sign and more digits, as
// ISO 8601's expanded years). std::invalid_argument otherwise.
std::string format_iso8601_time(double unix_time_utc_s, int utc_offset_min,
                                bool utc_designator = false);

// The UTC offset (minutes, daylight saving time included) of the IANA time zone `zone`, e.g.
// "Europe/Paris", at the instant rounded to the second. std::invalid_argument for an unknown
// zone.
int utc_offset_min_in_zone(double unix_time_utc_s, std::string_view zone);

// The instant as the local time of `zone` with that offset: "2024-07-01T14:00:00+02:00".
std::string format_iso8601_time_in_zone(double unix_time_utc_s, std::string_view zone);

}  // namespace clearsky::api
