// A sliding window of build start times per client.
#include "server/tables/build_rate_limiter.h"

#include <algorithm>
#include <cmath>

namespace clearsky::server {

BuildRateLimiter::BuildRateLimiter(std::size_t builds_per_window, std::chrono::seconds window)
    : builds_per_window_(builds_per_window), window_(std::max(window, std::chrono::seconds(1))) {}

void BuildRateLimiter::forget_before(Clock::time_point oldest_kept) {
  for (auto it = starts_.begin(); it != starts_.end();) {
    auto& starts = it->second;
    while (!starts.empty() && starts.front() < oldest_kept) starts.pop_front();
    it = starts.empty() ? starts_.erase(it) : std::next(it);
  }
}

int BuildRateLimiter::seconds_until_allowed(const std::string& client, Clock::time_point now) {
  if (builds_per_window_ == 0 || client.empty()) return 0;
  forget_before(now - window_);
  const auto it = starts_.find(client);
  if (it == starts_.end() || it->second.size() < builds_per_window_) return 0;
  // The oldest start that keeps the client at the limit leaves the window at start + window.
  const auto& starts = it->second;
  const Clock::time_point frees = starts[starts.size() - builds_per_window_] + window_;
  const double seconds = std::chrono::duration<double>(frees - now).count();
  return std::max(1, static_cast<int>(std::ceil(seconds)));
}

void BuildRateLimiter::record(const std::string& client, Clock::time_point now) {
  if (builds_per_window_ == 0 || client.empty()) return;
  auto& starts = starts_[client];
  starts.push_back(now);
  // Only the newest builds_per_window starts can decide a later answer.
  while (starts.size() > builds_per_window_) starts.pop_front();
}

}  // namespace clearsky::server
