// A small strict ISO 8601 date-time parser (iso8601_time.h): fixed-width fields are read in
// order, each checked, and the civil date is turned into days since 1970 with std::chrono.
#include "api/parse/iso8601_time.h"

#include <chrono>
#include <cstddef>
#include <optional>

#include "api/parse/invalid_parameter.h"

namespace clearsky::api {
namespace {

// A cursor over the text that reads fixed-width digit fields and literal characters.
class Reader {
 public:
  explicit Reader(std::string_view text) : text_(text) {}

  bool done() const { return pos_ == text_.size(); }
  std::optional<char> peek() const {
    return done() ? std::nullopt : std::optional<char>(text_[pos_]);
  }
  bool accept(char c) {
    if (peek() != c) return false;
    ++pos_;
    return true;
  }
  // Exactly `width` decimal digits.
  std::optional<int> digits(std::size_t width) {
    if (text_.size() - pos_ < width) return std::nullopt;
    int value = 0;
    for (std::size_t i = 0; i < width; ++i) {
      const char c = text_[pos_ + i];
      if (c < '0' || c > '9') return std::nullopt;
      value = value * 10 + (c - '0');
    }
    pos_ += width;
    return value;
  }
  // One or more digits after a decimal mark, as a fraction in [0, 1).
  std::optional<double> fraction() {
    double value = 0.0;
    double scale = 0.1;
    const std::size_t start = pos_;
    while (!done() && text_[pos_] >= '0' && text_[pos_] <= '9') {
      value += scale * (text_[pos_] - '0');
      scale /= 10.0;
      ++pos_;
    }
    if (pos_ == start) return std::nullopt;
    return value;
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
};

}  // namespace

Iso8601Time parse_iso8601_time(std::string_view text, const std::string& parameter) {
  const std::string shown = quoted(text);
  const auto fail = [&](const std::string& why) -> InvalidParameter {
    return InvalidParameter(
        parameter, why + " in " + shown +
                       "; expected an ISO 8601 time with offset such as 2013-05-27T11:45:00-04:00");
  };

  Reader in(text);
  const auto year = in.digits(4);
  if (!year || !in.accept('-')) throw fail("no four-digit year followed by '-'");
  const auto month = in.digits(2);
  if (!month || !in.accept('-')) throw fail("no two-digit month followed by '-'");
  const auto day = in.digits(2);
  if (!day) throw fail("no two-digit day");
  if (!in.accept('T') && !in.accept('t')) throw fail("no 'T' between date and time");
  const auto hour = in.digits(2);
  if (!hour || !in.accept(':')) throw fail("no two-digit hour followed by ':'");
  const auto minute = in.digits(2);
  if (!minute) throw fail("no two-digit minute");
  int second = 0;
  double fraction = 0.0;
  if (in.accept(':')) {
    const auto s = in.digits(2);
    if (!s) throw fail("no two-digit second after ':'");
    second = *s;
    if (in.accept('.') || in.accept(',')) {
      const auto f = in.fraction();
      if (!f) throw fail("no digits after the decimal mark");
      fraction = *f;
    }
  }

  Iso8601Time out;
  if (in.accept('Z') || in.accept('z')) {
    out.utc_designator = true;
  } else if (in.peek() == '+' || in.peek() == '-') {
    const int sign = in.accept('-') ? -1 : 1;
    in.accept('+');
    const auto offset_hours = in.digits(2);
    if (!offset_hours) throw fail("no two-digit hour in the UTC offset");
    int offset_minutes = 0;
    if (!in.done()) {
      in.accept(':');
      const auto m = in.digits(2);
      if (!m) throw fail("no two-digit minutes in the UTC offset");
      offset_minutes = *m;
    }
    if (*offset_hours > 18 || offset_minutes > 59 || (*offset_hours == 18 && offset_minutes > 0)) {
      throw fail("UTC offset beyond 18 hours");
    }
    out.utc_offset_min = sign * (*offset_hours * 60 + offset_minutes);
  } else if (in.done()) {
    throw fail("no UTC offset or Z");
  } else {
    throw fail("unexpected characters");
  }
  if (!in.done()) throw fail("unexpected characters after the UTC offset");

  const std::chrono::year_month_day date{std::chrono::year(*year),
                                         std::chrono::month(static_cast<unsigned>(*month)),
                                         std::chrono::day(static_cast<unsigned>(*day))};
  if (*month < 1 || *month > 12) throw fail("month out of 01-12");
  if (!date.ok()) throw fail("day out of range for the month");
  if (*hour > 23) throw fail("hour out of 00-23");
  if (*minute > 59) throw fail("minute out of 00-59");
  if (second > 59) throw fail("second out of 00-59 (leap seconds are not supported)");

  const double days = std::chrono::sys_days(date).time_since_epoch().count();
  const double local_s = days * 86400.0 + *hour * 3600.0 + *minute * 60.0 + second + fraction;
  out.unix_time_utc_s = local_s - out.utc_offset_min * 60.0;
  return out;
}

}  // namespace clearsky::api
