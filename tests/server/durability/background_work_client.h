// A client of the background-work routes (evaluation tickets, fits) of a real `clearsky serve`
// for the durability tests: token-bearing requests, JSON answers, and the wait for a queued or
// running piece of work to end (docs/data-api.md "Durability").
#pragma once

#include <httplib.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "tests/server/http/serve_process.h"

namespace clearsky::server::testing {

inline constexpr const char* kDurabilityToken = "t0ken";

// A client of `server` that sends the write token, with generous timeouts (a loaded machine or
// a sanitizer build is several times slower).
inline httplib::Client token_client(const ServeProcess& server) {
  httplib::Client c("127.0.0.1", server.port());
  c.set_bearer_token_auth(kDurabilityToken);
  c.set_read_timeout(60, 0);
  c.set_write_timeout(60, 0);
  return c;
}

// GET path as JSON: null when the server did not answer, discarded when the body is not JSON.
inline nlohmann::json get_json(httplib::Client& c, const std::string& path) {
  const auto r = c.Get(path.c_str());
  if (!r) return nullptr;
  return nlohmann::json::parse(r->body, nullptr, false);
}

// Polls the work at `location` until its status is neither queued nor running (or `within`
// has passed); returns its last answer.
inline nlohmann::json await_end(httplib::Client& c, const std::string& location,
                                std::chrono::seconds within = std::chrono::seconds(120)) {
  nlohmann::json last;
  const auto deadline = std::chrono::steady_clock::now() + within;
  while (std::chrono::steady_clock::now() < deadline) {
    last = get_json(c, location);
    if (last["status"] != "queued" && last["status"] != "running") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return last;
}

}  // namespace clearsky::server::testing
