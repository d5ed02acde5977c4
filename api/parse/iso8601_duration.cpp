// ISO 8601 durations (iso8601_duration.h).
#include "api/parse/iso8601_duration.h"

#include <charconv>

#include "api/error/api_error.h"

namespace clearsky::api {

long long parse_iso8601_duration_s(std::string_view text, const std::string& parameter) {
  const auto refuse = [&](const std::string& why) {
    return invalid_parameter(parameter,
                             "must be an ISO 8601 duration such as PT1H, PT10M or "
                             "P1D (" +
                                 why + "), got " + std::string(text));
  };
  if (text.size() < 3 || text.front() != 'P') throw refuse("it starts with P");
  constexpr long long kMaxSeconds = 100LL * 366 * 86400;
  long long total = 0;
  bool in_time = false;
  bool any = false;
  // The designators allowed next, in order: D before T, then H, M, S.
  std::string_view remaining = text.substr(1);
  std::string_view order = "D";
  while (!remaining.empty()) {
    if (remaining.front() == 'T') {
      if (in_time) throw refuse("one T");
      in_time = true;
      order = "HMS";
      remaining.remove_prefix(1);
      if (remaining.empty()) throw refuse("a time part after T");
      continue;
    }
    long long value = 0;
    const auto [end, ec] =
        std::from_chars(remaining.data(), remaining.data() + remaining.size(), value);
    if (ec != std::errc() || end == remaining.data() || value < 0 || value > kMaxSeconds)
      throw refuse("whole numbers before each designator");
    remaining.remove_prefix(static_cast<std::size_t>(end - remaining.data()));
    if (remaining.empty()) throw refuse("a designator after each number");
    const char designator = remaining.front();
    const std::size_t at = order.find(designator);
    if (at == std::string_view::npos) throw refuse("D, then T and H, M, S in that order");
    order.remove_prefix(at + 1);
    remaining.remove_prefix(1);
    const long long unit = designator == 'D'   ? 86400
                           : designator == 'H' ? 3600
                           : designator == 'M' ? 60
                                               : 1;
    total += value * unit;
    if (total > kMaxSeconds) throw refuse("at most 100 years");
    any = true;
  }
  if (!any) throw refuse("a number and a designator");
  if (total <= 0)
    throw invalid_parameter(parameter, "must be longer than zero, got " + std::string(text));
  return total;
}

}  // namespace clearsky::api
