// ISO 8601 text of an instant at a UTC offset, to the nearest second:
// "2003-10-17T06:12:43-07:00", or "...Z" when asked for the UTC designator (the form that
// api/parse/iso8601_time.h reads back).
#pragma once

#include <string>

namespace clearsky::api {

// utc_offset_min in [-1080, 1080]; unix_time_utc_s finite (years before 0000 or after 9999 are
// written with a sign and more digits, as ISO 8601's expanded years).
std::string format_iso8601_time(double unix_time_utc_s, int utc_offset_min,
                                bool utc_designator = false);

}  // namespace clearsky::api
