// Strict ISO 8601 date-time parsing (iso8601_time.h): the text's shape is checked by regular
// expressions (fixed-width fields), the calendar and the IANA time zones are date/tz's.
#include "api/parse/iso8601_time.h"

#include <date/date.h>
#include <date/tz.h>

#include <charconv>
#include <chrono>
#include <regex>
#include <stdexcept>

#include "api/error/api_error.h"

namespace clearsky::api {
namespace {

// A text in double quotes, for messages.
std::string quoted(std::string_view text) { return '"' + std::string(text) + '"'; }

constexpr int kMaxUtcOffsetMin = 14 * 60;

// YYYY-MM-DDThh:mm[:ss[.fff]] at the start of the text (the decimal mark may be ',').
const std::regex& date_time_pattern() {
  static const std::regex pattern(
      "([0-9]{4})-([0-9]{2})-([0-9]{2})[Tt]([0-9]{2}):([0-9]{2})"
      "(?::([0-9]{2})(?:[.,]([0-9]+))?)?");
  return pattern;
}

// Z, or +hh:mm, +hhmm, +hh (and with '-').
const std::regex& utc_offset_pattern() {
  static const std::regex pattern("[Zz]|([+-])([0-9]{2})(?::?([0-9]{2}))?");
  return pattern;
}

// A civil date and time of day, each field in range.
struct LocalTime {
  date::year_month_day date;
  int hour = 0;
  int minute = 0;
  int second = 0;
  double fraction = 0.0;  // of a second, in [0, 1)

  // Seconds since 1970-01-01T00:00:00 of the same calendar (no offset applied).
  double seconds_since_epoch() const {
    const double days = date::sys_days(date).time_since_epoch().count();
    return days * 86400.0 + hour * 3600.0 + minute * 60.0 + second + fraction;
  }
  date::local_seconds whole_seconds() const {
    return date::local_days(date) + std::chrono::hours(hour) + std::chrono::minutes(minute) +
           std::chrono::seconds(second);
  }
};

class Iso8601Reader {
 public:
  Iso8601Reader(std::string_view text, const std::string& parameter)
      : text_(text), parameter_(parameter) {}

  ApiError fail(const std::string& why) const {
    return invalid_parameter(
        parameter_,
        why + " in " + quoted(text_) +
            "; expected an ISO 8601 time with offset such as 2013-05-27T11:45:00-04:00");
  }

  // The date and time at the start of the text, checked against the calendar; the rest of the
  // text (the offset, if any) is left in rest().
  LocalTime local_time() {
    std::cmatch m;
    if (!std::regex_search(text_.data(), text_.data() + text_.size(), m, date_time_pattern(),
                           std::regex_constants::match_continuous)) {
      throw fail("no date and time of the form YYYY-MM-DDThh:mm[:ss[.fff]]");
    }
    rest_ = text_.substr(static_cast<std::size_t>(m.length(0)));
    LocalTime t;
    const int month = std::stoi(m.str(2));
    t.date = date::year(std::stoi(m.str(1))) / date::month(static_cast<unsigned>(month)) /
             date::day(static_cast<unsigned>(std::stoi(m.str(3))));
    t.hour = std::stoi(m.str(4));
    t.minute = std::stoi(m.str(5));
    if (m[6].matched) t.second = std::stoi(m.str(6));
    if (m[7].matched) {
      const std::string fraction = "0." + m.str(7);
      std::from_chars(fraction.data(), fraction.data() + fraction.size(), t.fraction);
    }
    if (month < 1 || month > 12) throw fail("month out of 01-12");
    if (!t.date.ok()) throw fail("day out of range for the month");
    if (t.hour > 23) throw fail("hour out of 00-23");
    if (t.minute > 59) throw fail("minute out of 00-59");
    if (t.second > 59) throw fail("second out of 00-59 (leap seconds are not supported)");
    return t;
  }

  std::string_view rest() const { return rest_; }

  // The UTC offset or Z that must make up the rest of the text.
  void utc_offset(Iso8601Time& out) const {
    if (rest_.empty()) throw fail("no UTC offset or Z");
    std::cmatch m;
    if (!std::regex_match(rest_.data(), rest_.data() + rest_.size(), m, utc_offset_pattern())) {
      throw fail("no UTC offset (Z, +hh:mm, +hhmm or +hh) after the time");
    }
    if (!m[1].matched) {
      out.utc_designator = true;
      out.utc_offset_min = 0;
      return;
    }
    const int hours = std::stoi(m.str(2));
    const int minutes = m[3].matched ? std::stoi(m.str(3)) : 0;
    if (minutes > 59) throw fail("UTC offset minutes out of 00-59");
    if (hours * 60 + minutes > kMaxUtcOffsetMin) throw fail("UTC offset beyond 14 hours");
    out.utc_offset_min = (m.str(1) == "-" ? -1 : 1) * (hours * 60 + minutes);
  }

 private:
  std::string_view text_;
  std::string_view rest_;
  const std::string& parameter_;
};

}  // namespace

int parse_utc_offset_minutes(std::string_view text, const std::string& parameter) {
  std::cmatch m;
  if (!std::regex_match(text.data(), text.data() + text.size(), m, utc_offset_pattern()))
    throw invalid_parameter(parameter, "not a UTC offset: " + quoted(text) +
                                           "; expected Z, +hh:mm, +hhmm or +hh such as -04:00");
  if (!m[1].matched) return 0;
  const int hours = std::stoi(m.str(2));
  const int minutes = m[3].matched ? std::stoi(m.str(3)) : 0;
  if (minutes > 59)
    throw invalid_parameter(parameter, "UTC offset minutes out of 00-59 in " + quoted(text));
  if (hours * 60 + minutes > kMaxUtcOffsetMin)
    throw invalid_parameter(parameter, "UTC offset beyond 14 hours in " + quoted(text));
  return (m.str(1) == "-" ? -1 : 1) * (hours * 60 + minutes);
}

namespace {

// The zone of the system's tz database; a name it does not hold is the client's error, a
// missing database the server's.
const date::time_zone& locate_zone(std::string_view zone, const std::string& zone_parameter) {
  try {
    (void)date::get_tzdb();
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("time zone database unavailable: ") + e.what());
  }
  try {
    return *date::locate_zone(zone);
  } catch (const std::exception&) {
    throw invalid_parameter(zone_parameter, "unknown time zone " + quoted(zone) +
                                                "; expected an IANA time zone name such as "
                                                "Europe/Paris or America/New_York");
  }
}

}  // namespace

Iso8601Time parse_iso8601_time(std::string_view text, const std::string& parameter) {
  Iso8601Reader reader(text, parameter);
  const LocalTime local = reader.local_time();
  Iso8601Time out;
  reader.utc_offset(out);
  out.unix_time_utc_s = local.seconds_since_epoch() - out.utc_offset_min * 60.0;
  return out;
}

Iso8601Time parse_iso8601_local_time(std::string_view text, std::string_view zone,
                                     const std::string& parameter,
                                     const std::string& zone_parameter) {
  Iso8601Reader reader(text, parameter);
  const LocalTime local = reader.local_time();
  if (!reader.rest().empty()) {
    throw invalid_parameter(parameter, "unexpected characters after the time in " + quoted(text) +
                                           "; with " + zone_parameter +
                                           " give the local time without offset, such as "
                                           "2013-05-27T11:45:00");
  }
  const date::time_zone& time_zone = locate_zone(zone, zone_parameter);
  const date::local_info info = time_zone.get_info(local.whole_seconds());
  if (info.result == date::local_info::nonexistent) {
    throw invalid_parameter(parameter, quoted(text) + " does not exist in " + std::string(zone) +
                                           " (the clocks skip it when they go forward)");
  }
  // Unique, or ambiguous (the clocks go back): the first of the two instants.
  const std::chrono::seconds offset = info.first.offset;
  Iso8601Time out;
  out.unix_time_utc_s = local.seconds_since_epoch() - static_cast<double>(offset.count());
  // Whole minutes (local mean times before standard time had offsets with seconds).
  out.utc_offset_min = static_cast<int>(offset.count() / 60);
  return out;
}

}  // namespace clearsky::api
