// A 5-field cron schedule in UTC ("minute hour day-of-month month day-of-week", as crontab(5)):
// each field is "*", a value, a range "a-b", a step "*/n", "a-b/n" or "a/n" (a to the field's
// maximum), or a comma-separated list of those; months and days of the week also take English
// three-letter names (jan..dec, sun..sat); day of week 0..7 with 0 and 7 both Sunday.
// Day rule (Vixie cron, which crontab(5) documents): when both day fields are restricted (do not
// start with "*"), a day matches if EITHER matches; otherwise both must match (the "*" one
// matches every day). Times are unix seconds; a schedule fires at the start of a minute.
// Value type; thread-safe once built.
#pragma once

#include <bitset>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace clearsky::api {

class CronSchedule {
 public:
  // Throws std::invalid_argument ("schedule: ...") for a malformed expression or one that never
  // fires (such as "0 0 31 4 *", April 31).
  static CronSchedule parse(std::string_view text);

  // The first firing instant strictly after unix_time_s (a whole minute), or none within the
  // next 28 years (a full cycle of the Gregorian weekdays over leap years).
  std::optional<std::int64_t> next_after(std::int64_t unix_time_s) const;
  // Whether the minute containing unix_time_s is a firing minute.
  bool matches(std::int64_t unix_time_s) const;

  const std::string& text() const { return text_; }

 private:
  bool day_matches(int day_of_month, unsigned month, unsigned weekday) const;

  std::string text_;
  std::bitset<60> minutes_;
  std::bitset<24> hours_;
  std::bitset<32> days_of_month_;  // 1..31
  std::bitset<13> months_;         // 1..12
  std::bitset<7> weekdays_;        // 0 = Sunday
  bool day_of_month_restricted_ = false;
  bool weekday_restricted_ = false;
};

}  // namespace clearsky::api
