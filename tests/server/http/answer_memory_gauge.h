// The answer memory budget's gauge of GET /metrics, read by the tests of
// api/http/answer_memory_budget.h against a real `clearsky serve`.
#pragma once

#include <regex>
#include <string>

#include "tests/server/http/watched_serve_process.h"

namespace clearsky::server::testing {

// clearsky_answer_memory_bytes{state="reserved"} of GET /metrics (-1 when absent).
inline double reserved_answer_bytes(const WatchedServeProcess& server) {
  auto client = server.client();
  const auto r = client.Get("/metrics");
  if (!r || r->status != 200) return -1;
  std::smatch m;
  static const std::regex kGauge(R"(clearsky_answer_memory_bytes\{state="reserved"\} (\S+))");
  if (!std::regex_search(r->body, m, kGauge)) return -1;
  return std::stod(m[1].str());
}

}  // namespace clearsky::server::testing
