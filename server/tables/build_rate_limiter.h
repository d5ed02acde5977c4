// The per-client limit on table builds (docs/threat-model.md "exhaust memory with builds"):
// each new configuration a request asks for builds tables, so a client may start at most
// `builds_per_window` builds within any `window` (a sliding window over the start times of its
// builds); beyond that the table store answers 429 + Retry-After naming `build_rate`. Only
// builds a client triggered count: requests served by built tables, by a build already under
// way (single flight) or refused for another reason do not. Clients are told apart by the
// network address the HTTP layer saw (behind a proxy, the proxy's: limits per end client
// belong to the front, docs/deployment.md). Memory: the start times within the window, at most
// builds_per_window per client; older ones are forgotten at every call.
// Not thread-safe: the table store calls it under its own lock.
#pragma once

#include <chrono>
#include <cstddef>
#include <deque>
#include <map>
#include <string>

namespace clearsky::server {

class BuildRateLimiter {
 public:
  using Clock = std::chrono::steady_clock;

  // builds_per_window 0: no limit.
  BuildRateLimiter(std::size_t builds_per_window, std::chrono::seconds window);

  // 0 when `client` may trigger a build at `now`; otherwise the whole seconds (>= 1) until it
  // may, for Retry-After. An empty client (the server's own work) is never limited.
  int seconds_until_allowed(const std::string& client, Clock::time_point now);
  // Counts a build `client` triggered at `now`.
  void record(const std::string& client, Clock::time_point now);
  // Clients with builds inside the window (what the limiter holds in memory).
  std::size_t clients() const { return starts_.size(); }
  std::size_t builds_per_window() const { return builds_per_window_; }
  std::chrono::seconds window() const { return window_; }

 private:
  void forget_before(Clock::time_point oldest_kept);

  std::size_t builds_per_window_;
  std::chrono::seconds window_;
  std::map<std::string, std::deque<Clock::time_point>> starts_;  // oldest first
};

}  // namespace clearsky::server
