// A server with the data endpoints (datasets, imports, evaluations, fits, jobs) on an ephemeral
// loopback port, on a fresh database in a temporary folder, with the analytic test sky for the
// query endpoints, for tests that talk to it with cpp-httplib's client.
#pragma once

#include <gtest/gtest.h>
#include <httplib.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "api/evaluation/evaluation_pool.h"
#include "api/fits/fit_pool.h"
#include "api/imports/import_pool.h"
#include "models/registry.h"
#include "server/http/http_server.h"
#include "storage/schema/migrations.h"
#include "tests/support/temp_dir.h"
#include "tests/support/test_sky_model.h"

namespace clearsky::server::testing {

class DataServerFixture : public ::testing::Test {
 protected:
  void start(std::optional<std::string> token, std::size_t payload_max_bytes = 8u << 20,
             std::size_t max_upload_bytes = 64u << 20, std::vector<std::string> cors_origins = {}) {
    db_path = dir.path / "sky.db";
    storage::open_database(db_path);
    ServerConfig config;
    config.host = "127.0.0.1";
    config.port = 0;
    config.threads = 8;
    config.payload_max_bytes = payload_max_bytes;
    config.max_upload_bytes = max_upload_bytes;
    config.cors_origins = std::move(cors_origins);
    tables =
        std::make_unique<TableStore>(clearsky::testing::test_factories(), TableStore::Options{});
    const auto path = db_path;
    pool = std::make_unique<api::EvaluationPool>([path] { return storage::Database::open(path); },
                                                 registered_models());
    imports = std::make_unique<api::ImportPool>([path] { return storage::Database::open(path); });
    fits = std::make_unique<api::FitPool>([path] { return storage::Database::open(path); });
    auth = std::make_unique<WriteAuthorizer>(token);
    services.db_path = db_path;
    services.upload_dir = dir.path / "uploads";
    services.upload_max_bytes = max_upload_bytes;
    services.import_roots = api::ImportRoots(import_roots);
    services.evaluations = pool.get();
    services.imports = imports.get();
    services.fits = fits.get();
    services.models = registered_models();
    services.software_version = "test";
    http = std::make_unique<HttpServer>(config, *tables, metrics);
    http->add_data_services(services, *auth);
    port = http->bind();
    thread = std::thread([this] { http->listen(); });
    for (int i = 0; i < 400 && !http->running(); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_TRUE(http->running());
  }
  void TearDown() override {
    if (http) http->stop();
    if (thread.joinable()) thread.join();
    http.reset();
    pool.reset();
    imports.reset();
    fits.reset();
  }
  httplib::Client client(const std::string& token = "") const {
    httplib::Client c("127.0.0.1", port);
    c.set_read_timeout(60, 0);
    if (!token.empty()) c.set_bearer_token_auth(token.c_str());
    return c;
  }
  static nlohmann::json body(const httplib::Result& r) { return nlohmann::json::parse(r->body); }
  // Polls an import's Location until it ends.
  nlohmann::json finished_import(const httplib::Result& accepted) const {
    const std::string location = accepted->get_header_value("Location");
    nlohmann::json state;
    for (int i = 0; i < 1500; ++i) {
      state = body(client().Get(location.c_str()));
      if (state["status"] == "succeeded" || state["status"] == "failed") break;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return state;
  }

  clearsky::testing::TempDir dir;
  // Where path= imports may read (set before start(); none: refused).
  std::vector<std::string> import_roots;
  std::filesystem::path db_path;
  Metrics metrics;
  std::unique_ptr<TableStore> tables;
  std::unique_ptr<api::EvaluationPool> pool;
  std::unique_ptr<api::ImportPool> imports;
  std::unique_ptr<api::FitPool> fits;
  std::unique_ptr<WriteAuthorizer> auth;
  api::DataServices services;
  std::unique_ptr<HttpServer> http;
  std::thread thread;
  int port = 0;
};

}  // namespace clearsky::server::testing
