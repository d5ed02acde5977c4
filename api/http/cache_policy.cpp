// Cache-Control, ETag and If-None-Match (cache_policy.h).
#include "api/http/cache_policy.h"

#include <xxhash.h>

namespace clearsky::api {

std::string_view cache_control(Caching caching) {
  switch (caching) {
    case Caching::revalidate:
      return "no-cache";
    case Caching::deterministic:
      // A day: answers change only with a new server build (its models' numbers), and the
      // tag lets a client revalidate cheaply after that.
      return "public, max-age=86400";
    case Caching::no_store:
      break;
  }
  return "no-store";
}

std::string strong_etag(std::string_view body) {
  const XXH128_hash_t hash = XXH3_128bits(body.data(), body.size());
  // Written digit by digit: snprintf cost as much as the hash on a typical answer.
  static constexpr char hex[] = "0123456789abcdef";
  std::string tag(34, '"');
  for (int i = 0; i < 16; ++i) {
    const int shift = 60 - 4 * i;
    tag[1 + i] = hex[(hash.high64 >> shift) & 0xF];
    tag[17 + i] = hex[(hash.low64 >> shift) & 0xF];
  }
  return tag;
}

bool if_none_match(std::string_view header_value, std::string_view etag) {
  const auto trim = [](std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
  };
  // The weak comparison ignores W/ on either side.
  if (etag.starts_with("W/")) etag.remove_prefix(2);
  while (!header_value.empty()) {
    const std::size_t comma = header_value.find(',');
    std::string_view tag = trim(header_value.substr(0, comma));
    header_value =
        comma == std::string_view::npos ? std::string_view() : header_value.substr(comma + 1);
    if (tag == "*") return true;
    if (tag.starts_with("W/")) tag.remove_prefix(2);
    if (tag == etag) return true;
  }
  return false;
}

void apply_caching(Caching caching, const ApiRequest& request, ApiResponse& response) {
  if (response.header("Cache-Control")) return;
  const bool success = response.status >= 200 && response.status < 300;
  if (!success || caching == Caching::no_store) {
    response.headers.emplace_back("Cache-Control", "no-store");
    return;
  }
  response.headers.emplace_back("Cache-Control", std::string(cache_control(caching)));
  if (response.stream) return;
  const std::string etag = strong_etag(response.body);
  response.headers.emplace_back("ETag", etag);
  const bool safe = request.method == "GET" || request.method == "HEAD";
  const auto condition = request.header("If-None-Match");
  if (safe && condition && if_none_match(*condition, etag)) {
    response.status = 304;
    response.body.clear();
  }
}

}  // namespace clearsky::api
