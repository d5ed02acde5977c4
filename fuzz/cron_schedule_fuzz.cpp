// The 5-field cron schedules of jobs (api/jobs/cron_schedule.h). An input is the expression,
// optionally followed by a newline and a unix time in seconds (the instant to look after).
//
// Invariants (docs/fuzzing.md): a refusal is a std::invalid_argument whose message starts with
// "schedule:", nothing else escapes; an accepted schedule's next firing after t is a whole
// minute strictly after t, matches, is within 28 years, and no earlier minute after t matches
// (checked over the first day after t, minute by minute).
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>

#include "api/jobs/cron_schedule.h"
#include "fuzz/support/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace clearsky;
  using namespace clearsky::fuzz;
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t newline = input.find('\n');
  const std::string text = input.substr(0, newline);
  // 2026-11-21T09:30:17Z unless the input names another instant (within years 1900..2200).
  std::int64_t after = 1795253417;
  if (newline != std::string::npos) {
    const long long t = std::strtoll(input.c_str() + newline + 1, nullptr, 10);
    if (t > -2208988800LL && t < 7258118400LL) after = t;
  }

  std::optional<api::CronSchedule> schedule;
  try {
    schedule = api::CronSchedule::parse(text);
  } catch (const std::invalid_argument& e) {
    check(std::string(e.what()).starts_with("schedule:"),
          std::string("refusal without 'schedule:': ") + e.what(), input);
    return 0;
  } catch (const std::exception& e) {
    fail(std::string("not an invalid_argument: ") + e.what(), input);
  }
  const std::optional<std::int64_t> next = schedule->next_after(after);
  // parse() refuses a schedule that never fires.
  check(next.has_value(), "an accepted schedule never fires", input);
  check(*next > after, "next firing not after the instant", input);
  check(*next % 60 == 0, "next firing not a whole minute", input);
  check(*next - after <= 28LL * 366 * 86400, "next firing beyond 28 years", input);
  check(schedule->matches(*next), "next firing does not match", input);
  const std::int64_t first_minute = (after / 60 + 1) * 60;
  for (std::int64_t m = first_minute; m < *next && m < first_minute + 86400; m += 60)
    check(!schedule->matches(m), "a minute before the next firing matches", input);
  return 0;
}
