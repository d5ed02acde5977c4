// A real `clearsky serve` for the client library's tests (tests/server/http/serve_process.h) on
// a free loopback port, with a token file for the writes, and a clearsky::client::Client
// pointed at it; ready() waits (generously, for a loaded machine) until /readyz answers 200.
#pragma once

#include <clearsky/client/client.h>
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "tests/server/http/serve_process.h"
#include "tests/support/temp_dir.h"

namespace clearsky::client::testing {

inline constexpr const char* kToken = "client-test-token";

class ClientServer {
 public:
  ClientServer(const std::vector<std::string>& extra, const std::string& models) {
    const auto token_file = dir_.path / "token";
    std::ofstream(token_file) << kToken << '\n';
    std::vector<std::string> arguments = {"--token-file", token_file.string()};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    process_ = std::make_unique<server::testing::ServeProcess>(dir_.path, arguments, models);
  }

  int port() const { return process_->port(); }
  std::string log() const { return process_->log(); }
  ClientOptions options(bool with_token = true) const {
    ClientOptions options;
    options.base_url = "http://127.0.0.1:" + std::to_string(port());
    if (with_token) options.token = kToken;
    return options;
  }
  Client client(bool with_token = true) const { return Client(options(with_token)); }

  // Whether /readyz answered 200 within 180 s.
  bool ready() const {
    ClientOptions quick = options();
    quick.max_retries = 0;
    const Client c(quick);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(180);
    while (std::chrono::steady_clock::now() < deadline) {
      try {
        if (c.readiness() == "ready") return true;
      } catch (const Error&) {
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return false;
  }
  const std::filesystem::path& directory() const { return dir_.path; }

 private:
  clearsky::testing::TempDir dir_;
  std::unique_ptr<server::testing::ServeProcess> process_;
};

}  // namespace clearsky::client::testing
