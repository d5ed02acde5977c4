// A running server on an ephemeral loopback port, serving the analytic test sky, for tests
// that talk to it with a real HTTP client (cpp-httplib's).
#pragma once

#include <gtest/gtest.h>
#include <httplib.h>

#include <thread>

#include "server/http/http_server.h"
#include "tests/support/test_sky_model.h"

namespace clearsky::server::testing {

class ServerFixture : public ::testing::Test {
 protected:
  void SetUp() override { start({}); }
  void TearDown() override { stop(); }

  void start(ServerConfig config) {
    config.host = "127.0.0.1";
    config.port = 0;
    config.threads = config.threads ? config.threads : 16;
    TableStore::Options options;
    options.build_wait = std::chrono::milliseconds(config.build_wait_ms);
    options.retry_after_s = config.retry_after_s;
    tables = std::make_unique<TableStore>(clearsky::testing::test_factories(), options);
    tables->start_default_builds();
    http = std::make_unique<HttpServer>(config, *tables, metrics);
    port = http->bind();
    thread = std::thread([this] { http->listen(); });
    for (int i = 0; i < 400 && !(http->running() && tables->ready()); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ASSERT_TRUE(http->running());
  }
  void stop() {
    if (http) http->stop();
    if (thread.joinable()) thread.join();
    http.reset();
    tables.reset();
  }
  httplib::Client client() const {
    httplib::Client c("127.0.0.1", port);
    c.set_read_timeout(30, 0);
    c.set_tcp_nodelay(true);
    return c;
  }

  Metrics metrics;
  std::unique_ptr<TableStore> tables;
  std::unique_ptr<HttpServer> http;
  std::thread thread;
  int port = 0;
};

}  // namespace clearsky::server::testing
