// Parsing and next-firing computation of cron schedules (cron_schedule.h).
#include "api/jobs/cron_schedule.h"

#include <array>
#include <charconv>
#include <chrono>
#include <stdexcept>
#include <vector>

namespace clearsky::api {
namespace {

constexpr std::int64_t kMinuteS = 60;
constexpr std::int64_t kHourS = 3600;
constexpr std::int64_t kDayS = 86400;

struct FieldSpec {
  const char* name;
  int min;
  int max;
  const char* const* names;  // three-letter names of min, min + 1, ...; nullptr when none
};

constexpr const char* kMonthNames[] = {"jan", "feb", "mar", "apr", "may", "jun",  "jul",
                                       "aug", "sep", "oct", "nov", "dec", nullptr};
constexpr const char* kWeekdayNames[] = {"sun", "mon", "tue", "wed", "thu", "fri", "sat", nullptr};

constexpr std::array<FieldSpec, 5> kFields = {{
    {"minute", 0, 59, nullptr},
    {"hour", 0, 23, nullptr},
    {"day of month", 1, 31, nullptr},
    {"month", 1, 12, kMonthNames},
    {"day of week", 0, 7, kWeekdayNames},
}};

[[noreturn]] void fail(const FieldSpec& field, std::string_view text, const std::string& why) {
  throw std::invalid_argument("schedule: " + std::string(field.name) + " field \"" +
                              std::string(text) + "\": " + why);
}

char lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

int parse_value(const FieldSpec& field, std::string_view text, std::string_view whole) {
  if (field.names != nullptr && text.size() == 3) {
    for (int i = 0; field.names[i] != nullptr; ++i) {
      const char* n = field.names[i];
      if (lower(text[0]) == n[0] && lower(text[1]) == n[1] && lower(text[2]) == n[2])
        return field.min + i;
    }
  }
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size())
    fail(field, whole,
         "\"" + std::string(text) + "\" is not a number" + (field.names ? " or a name" : ""));
  if (value < field.min || value > field.max)
    fail(field, whole,
         std::to_string(value) + " is outside " + std::to_string(field.min) + "-" +
             std::to_string(field.max));
  return value;
}

// The values a field selects, as a bit per value from 0 to field.max.
std::vector<bool> parse_field(const FieldSpec& field, std::string_view text) {
  std::vector<bool> selected(static_cast<std::size_t>(field.max) + 1, false);
  if (text.empty()) fail(field, text, "empty");
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view item = text.substr(start, comma - start);
    if (item.empty()) fail(field, text, "empty list item");
    std::string_view range = item;
    int step = 1;
    const std::size_t slash = item.find('/');
    if (slash != std::string_view::npos) {
      range = item.substr(0, slash);
      const std::string_view step_text = item.substr(slash + 1);
      const auto [end, error] =
          std::from_chars(step_text.data(), step_text.data() + step_text.size(), step);
      if (step_text.empty() || error != std::errc() || end != step_text.data() + step_text.size() ||
          step < 1)
        fail(field, text, "the step \"" + std::string(step_text) + "\" is not a positive number");
    }
    int first = field.min;
    int last = field.max;
    if (range != "*") {
      const std::size_t dash = range.find('-');
      if (dash == std::string_view::npos) {
        first = parse_value(field, range, text);
        // "a/n" runs from a to the maximum; a lone value is itself.
        last = slash != std::string_view::npos ? field.max : first;
      } else {
        first = parse_value(field, range.substr(0, dash), text);
        last = parse_value(field, range.substr(dash + 1), text);
        if (last < first) fail(field, text, "the range " + std::string(range) + " runs backwards");
      }
    }
    for (int v = first; v <= last; v += step) selected[static_cast<std::size_t>(v)] = true;
    start = comma + 1;
  }
  return selected;
}

template <std::size_t N>
std::bitset<N> to_bits(const std::vector<bool>& selected, int offset = 0) {
  std::bitset<N> bits;
  for (std::size_t v = 0; v < selected.size(); ++v)
    if (selected[v]) bits.set((v + static_cast<std::size_t>(offset)) % N);
  return bits;
}

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  return a / b - ((a % b != 0) && ((a < 0) != (b < 0)) ? 1 : 0);
}

}  // namespace

CronSchedule CronSchedule::parse(std::string_view text) {
  std::vector<std::string_view> parts;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    const std::size_t begin = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\t') ++i;
    if (i > begin) parts.push_back(text.substr(begin, i - begin));
  }
  if (parts.size() != 5)
    throw std::invalid_argument("schedule: \"" + std::string(text) + "\" has " +
                                std::to_string(parts.size()) +
                                " fields; expected 5 (minute hour day-of-month month day-of-week)");
  CronSchedule s;
  s.text_ = std::string(text);
  s.minutes_ = to_bits<60>(parse_field(kFields[0], parts[0]));
  s.hours_ = to_bits<24>(parse_field(kFields[1], parts[1]));
  s.days_of_month_ = to_bits<32>(parse_field(kFields[2], parts[2]));
  s.months_ = to_bits<13>(parse_field(kFields[3], parts[3]));
  // 7 folds onto 0 (both Sunday).
  s.weekdays_ = to_bits<7>(parse_field(kFields[4], parts[4]));
  s.day_of_month_restricted_ = parts[2].front() != '*';
  s.weekday_restricted_ = parts[4].front() != '*';
  if (!s.next_after(0))
    throw std::invalid_argument("schedule: \"" + std::string(text) + "\" never fires");
  return s;
}

bool CronSchedule::day_matches(int day_of_month, unsigned month, unsigned weekday) const {
  if (!months_.test(month)) return false;
  const bool by_day = days_of_month_.test(static_cast<std::size_t>(day_of_month));
  const bool by_weekday = weekdays_.test(weekday);
  if (day_of_month_restricted_ && weekday_restricted_) return by_day || by_weekday;
  return by_day && by_weekday;
}

bool CronSchedule::matches(std::int64_t unix_time_s) const {
  using namespace std::chrono;
  const std::int64_t day = floor_div(unix_time_s, kDayS);
  const std::int64_t second_of_day = unix_time_s - day * kDayS;
  const sys_days date{days{day}};
  const year_month_day ymd{date};
  return day_matches(static_cast<int>(static_cast<unsigned>(ymd.day())),
                     static_cast<unsigned>(ymd.month()), weekday{date}.c_encoding()) &&
         hours_.test(static_cast<std::size_t>(second_of_day / kHourS)) &&
         minutes_.test(static_cast<std::size_t>((second_of_day % kHourS) / kMinuteS));
}

std::optional<std::int64_t> CronSchedule::next_after(std::int64_t unix_time_s) const {
  using namespace std::chrono;
  std::int64_t t = (floor_div(unix_time_s, kMinuteS) + 1) * kMinuteS;
  const std::int64_t limit_day = floor_div(t, kDayS) + 28 * 366;
  // Skip whole days, then whole hours, then minutes: at most a few thousand steps.
  for (;;) {
    const std::int64_t day = floor_div(t, kDayS);
    if (day > limit_day) return std::nullopt;
    const sys_days date{days{day}};
    const year_month_day ymd{date};
    if (!day_matches(static_cast<int>(static_cast<unsigned>(ymd.day())),
                     static_cast<unsigned>(ymd.month()), weekday{date}.c_encoding())) {
      t = (day + 1) * kDayS;
      continue;
    }
    const std::int64_t second_of_day = t - day * kDayS;
    const auto hour = static_cast<std::size_t>(second_of_day / kHourS);
    if (!hours_.test(hour)) {
      t = day * kDayS + static_cast<std::int64_t>(hour + 1) * kHourS;
      continue;
    }
    const auto minute = static_cast<std::size_t>((second_of_day % kHourS) / kMinuteS);
    if (!minutes_.test(minute)) {
      t += kMinuteS;
      continue;
    }
    return t;
  }
}

}  // namespace clearsky::api
