// The ISO 8601 time parsers of requests (api/parse/iso8601_time.h) and their formatter
// (api/encode/iso8601_time.h). An input is the time text, optionally followed by a newline and
// an IANA time zone name (then the time is read as a local time of that zone).
//
// Invariants (docs/fuzzing.md): a refusal is an ApiError 400 naming the time or zone parameter,
// nothing else escapes; an accepted time is a finite instant of years 0000..9999 (within a day,
// for the offset), with an offset of at most 14 hours; writing it back and reading that gives
// the same instant (to the rounding to a second) and the same offset.
#include <cmath>
#include <cstdint>
#include <string>

#include "api/encode/iso8601_time.h"
#include "api/error/api_error.h"
#include "api/parse/iso8601_time.h"
#include "fuzz/support/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace clearsky;
  using namespace clearsky::fuzz;
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t newline = input.find('\n');
  const std::string text = input.substr(0, newline);
  const bool zoned = newline != std::string::npos;
  const std::string zone = zoned ? input.substr(newline + 1) : std::string();

  api::Iso8601Time t;
  try {
    t = zoned ? api::parse_iso8601_local_time(text, zone, "time", "tz")
              : api::parse_iso8601_time(text, "time");
  } catch (const api::ApiError& e) {
    check(e.status() == 400, "refusal with status " + std::to_string(e.status()), input);
    check(e.parameter() == "time" || (zoned && e.parameter() == "tz"),
          "refusal naming '" + e.parameter() + "'", input);
    return 0;
  } catch (const std::exception& e) {
    fail(std::string("not an ApiError: ") + e.what(), input);
  }

  // 0000-01-01 minus 14 h to 9999-12-31T24:00 plus 14 h, in unix seconds.
  constexpr double kFirst = -62167219200.0 - 14 * 3600.0;
  constexpr double kLast = 253402300800.0 + 14 * 3600.0;
  check(std::isfinite(t.unix_time_utc_s), "non-finite instant", input);
  check(t.unix_time_utc_s >= kFirst && t.unix_time_utc_s <= kLast,
        "instant outside years 0000..9999: " + std::to_string(t.unix_time_utc_s), input);
  check(t.utc_offset_min >= -840 && t.utc_offset_min <= 840,
        "offset beyond 14 h: " + std::to_string(t.utc_offset_min), input);

  std::string written;
  try {
    written = api::format_iso8601_time(t.unix_time_utc_s, t.utc_offset_min, t.utc_designator);
  } catch (const std::exception& e) {
    fail(std::string("an accepted time cannot be written: ") + e.what(), input);
  }
  // Rounding to the second may carry past 9999-12-31T23:59:59 (an expanded year, which
  // requests do not take): nothing to read back then.
  if (written.starts_with('+') || written.starts_with('-')) return 0;
  api::Iso8601Time back;
  try {
    back = api::parse_iso8601_time(written, "time");
  } catch (const std::exception& e) {
    fail("the written time " + written + " does not read back: " + e.what(), input);
  }
  check(std::abs(back.unix_time_utc_s - t.unix_time_utc_s) <= 0.5 + 1e-6,
        "written as " + written + ", read back another instant", input);
  check(back.utc_offset_min == t.utc_offset_min, "written as " + written + ", another offset",
        input);
  return 0;
}
