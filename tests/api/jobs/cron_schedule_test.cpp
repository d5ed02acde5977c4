// Tests of the cron schedule (api/jobs/cron_schedule.h): field syntax, the day-of-month
// / day-of-week rule, and next-firing times across hour, day, month, year and leap-day edges,
// checked against calendar dates worked out by hand.
#include "api/jobs/cron_schedule.h"

#include <gtest/gtest.h>

#include <chrono>

namespace clearsky::api {
namespace {

std::int64_t utc(int y, unsigned mo, unsigned d, int h = 0, int mi = 0, int s = 0) {
  using namespace std::chrono;
  const sys_days day{year{y} / month{mo} / std::chrono::day{d}};
  return day.time_since_epoch().count() * 86400LL + h * 3600LL + mi * 60LL + s;
}

std::int64_t next(const char* schedule, std::int64_t after) {
  const auto t = CronSchedule::parse(schedule).next_after(after);
  EXPECT_TRUE(t.has_value()) << schedule;
  return t.value_or(-1);
}

TEST(CronSchedule, EveryMinuteFiresAtTheNextWholeMinute) {
  EXPECT_EQ(next("* * * * *", utc(2026, 11, 21, 10, 5, 0)), utc(2026, 11, 21, 10, 6));
  EXPECT_EQ(next("* * * * *", utc(2026, 11, 21, 10, 5, 59)), utc(2026, 11, 21, 10, 6));
  // Strictly after: a firing instant is not its own successor.
  EXPECT_EQ(next("* * * * *", utc(2026, 11, 21, 10, 6)), utc(2026, 11, 21, 10, 7));
}

TEST(CronSchedule, HourlyDailyAndYearEdges) {
  EXPECT_EQ(next("30 * * * *", utc(2026, 11, 21, 10, 30)), utc(2026, 11, 21, 11, 30));
  EXPECT_EQ(next("0 3 * * *", utc(2026, 11, 21, 3, 0, 1)), utc(2026, 11, 22, 3, 0));
  EXPECT_EQ(next("0 0 1 1 *", utc(2026, 6, 15)), utc(2027, 1, 1));
  EXPECT_EQ(next("59 23 31 12 *", utc(2026, 12, 31, 23, 59)), utc(2027, 12, 31, 23, 59));
}

TEST(CronSchedule, RangesStepsAndLists) {
  // Minutes 0, 15, 30, 45.
  EXPECT_EQ(next("*/15 * * * *", utc(2026, 1, 1, 8, 16)), utc(2026, 1, 1, 8, 30));
  EXPECT_EQ(next("*/15 * * * *", utc(2026, 1, 1, 8, 45)), utc(2026, 1, 1, 9, 0));
  // Hours 9..17 every 4: 9, 13, 17.
  EXPECT_EQ(next("0 9-17/4 * * *", utc(2026, 1, 1, 13, 0)), utc(2026, 1, 1, 17, 0));
  EXPECT_EQ(next("0 9-17/4 * * *", utc(2026, 1, 1, 17, 0)), utc(2026, 1, 2, 9, 0));
  // "a/n": from a to the maximum.
  EXPECT_EQ(next("50/5 * * * *", utc(2026, 1, 1, 8, 56)), utc(2026, 1, 1, 9, 50));
  // Lists mixing values and ranges.
  EXPECT_EQ(next("5,10-12 0 * * *", utc(2026, 1, 1, 0, 5)), utc(2026, 1, 1, 0, 10));
  EXPECT_EQ(next("5,10-12 0 * * *", utc(2026, 1, 1, 0, 12)), utc(2026, 1, 2, 0, 5));
}

TEST(CronSchedule, MonthAndWeekdayNames) {
  // 2026-11-21 is a Saturday; the next Monday is the 23rd.
  EXPECT_EQ(next("0 6 * * mon", utc(2026, 11, 21)), utc(2026, 11, 23, 6, 0));
  EXPECT_EQ(next("0 6 * * MON-wed", utc(2026, 11, 24, 7, 0)), utc(2026, 11, 25, 6, 0));
  EXPECT_EQ(next("0 0 1 Mar,sep *", utc(2026, 4, 1)), utc(2026, 9, 1));
}

TEST(CronSchedule, SundayIsZeroAndSeven) {
  const std::int64_t sunday = utc(2026, 11, 22, 6, 0);
  EXPECT_EQ(next("0 6 * * 0", utc(2026, 11, 21)), sunday);
  EXPECT_EQ(next("0 6 * * 7", utc(2026, 11, 21)), sunday);
  EXPECT_EQ(next("0 6 * * 5-7", utc(2026, 11, 21, 7, 0)), sunday);
}

TEST(CronSchedule, BothDayFieldsRestrictedMeansEither) {
  // The 13th, or any Friday: from Saturday 2026-11-21 the next Friday (27th) comes before
  // December 13th; from Saturday 2026-12-12, Sunday the 13th comes before Friday the 18th.
  EXPECT_EQ(next("0 0 13 * fri", utc(2026, 11, 21)), utc(2026, 11, 27));
  EXPECT_EQ(next("0 0 13 * fri", utc(2026, 12, 12)), utc(2026, 12, 13));
}

TEST(CronSchedule, OneDayFieldStarredMeansTheOtherAlone) {
  // Day of month 13 whatever the weekday; then Fridays whatever the day of month.
  EXPECT_EQ(next("0 0 13 * *", utc(2026, 11, 21)), utc(2026, 12, 13));
  EXPECT_EQ(next("0 0 * * fri", utc(2026, 11, 21)), utc(2026, 11, 27));
  // A stepped star is still a star for this rule: every other day of month AND Mondays.
  // Odd days: 1, 3, ...; the first odd-day Monday after 2026-11-21 is 2026-11-23.
  EXPECT_EQ(next("0 0 */2 * mon", utc(2026, 11, 21)), utc(2026, 11, 23));
  // Then Monday 30th (even) is skipped: the next odd Monday is 2026-12-07.
  EXPECT_EQ(next("0 0 */2 * mon", utc(2026, 11, 23)), utc(2026, 12, 7));
}

TEST(CronSchedule, LeapDay) {
  EXPECT_EQ(next("0 12 29 2 *", utc(2026, 1, 1)), utc(2028, 2, 29, 12, 0));
  // 2100 is not a leap year.
  EXPECT_EQ(next("0 0 29 2 *", utc(2096, 3, 1)), utc(2104, 2, 29));
}

TEST(CronSchedule, Matches) {
  const CronSchedule s = CronSchedule::parse("*/10 8-9 * * 1-5");
  EXPECT_TRUE(s.matches(utc(2026, 11, 23, 8, 20, 42)));  // Monday
  EXPECT_FALSE(s.matches(utc(2026, 11, 23, 8, 21)));
  EXPECT_FALSE(s.matches(utc(2026, 11, 22, 8, 20)));  // Sunday
  EXPECT_FALSE(s.matches(utc(2026, 11, 23, 10, 0)));
}

TEST(CronSchedule, NextAfterIsTheFirstMatchingMinute) {
  const CronSchedule s = CronSchedule::parse("7,37 */5 1-10,20 * tue");
  std::int64_t t = utc(2026, 1, 1);
  for (int i = 0; i < 40; ++i) {
    const std::int64_t n = *s.next_after(t);
    ASSERT_TRUE(s.matches(n));
    ASSERT_EQ(n % 60, 0);
    // No matching minute in between (checked minute by minute over the gap, up to a day).
    for (std::int64_t m = (t / 60 + 1) * 60; m < n && m < t + 86400; m += 60)
      ASSERT_FALSE(s.matches(m)) << m;
    t = n;
  }
}

TEST(CronSchedule, MalformedSchedulesAreRefusedWithTheField) {
  const auto message = [](const char* text) -> std::string {
    try {
      CronSchedule::parse(text);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_NE(message("* * * *").find("4 fields"), std::string::npos);
  EXPECT_NE(message("* * * * * *").find("6 fields"), std::string::npos);
  EXPECT_NE(message("60 * * * *").find("minute"), std::string::npos);
  EXPECT_NE(message("* 24 * * *").find("hour"), std::string::npos);
  EXPECT_NE(message("* * 0 * *").find("day of month"), std::string::npos);
  EXPECT_NE(message("* * * 13 *").find("month"), std::string::npos);
  EXPECT_NE(message("* * * * 8").find("day of week"), std::string::npos);
  EXPECT_NE(message("*/0 * * * *").find("step"), std::string::npos);
  EXPECT_NE(message("5-1 * * * *").find("backwards"), std::string::npos);
  EXPECT_NE(message("1,,2 * * * *").find("empty"), std::string::npos);
  EXPECT_NE(message("a * * * *").find("not a number"), std::string::npos);
  EXPECT_NE(message("* * * * funday").find("day of week"), std::string::npos);
  EXPECT_NE(message("-1 * * * *").find("minute"), std::string::npos);
  EXPECT_NE(message("0 0 31 4 *").find("never fires"), std::string::npos);
  EXPECT_NE(message("0 0 30 2 *").find("never fires"), std::string::npos);
  EXPECT_EQ(message(" 0  0\t* * * "), "accepted");
}

}  // namespace
}  // namespace clearsky::api
