// The HTTP boundary (docs/conventions.md "One HTTP boundary"): cpp-httplib wired to the api/
// handlers, in one place.
// - routes of HTTP API v1, docs/http-api.md (routes() lists them, for the OpenAPI coverage test);
// - one exception handler (ApiError -> its status; anything else, caught with catch (...),
//   -> 500), and one error format {"error": {"code", "message", "parameter"}}, also for
//   httplib's own errors (404 unknown path, 413 payload);
// - limits from ServerConfig: worker threads, bounded queue, payload, timeouts, keep-alive;
// - a structured access log line per request (spdlog logger "access") and Prometheus metrics.
// Thread-safety: start()/stop() from one controlling thread; requests run on the workers.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "server/config/server_config.h"
#include "server/http/data_routes.h"
#include "server/metrics/metrics.h"
#include "server/tables/table_store.h"

namespace httplib {
class Server;
}

namespace clearsky::server {

class HttpServer {
 public:
  HttpServer(const ServerConfig& config, TableStore& tables, Metrics& metrics);
  ~HttpServer();

  // Binds config.host:config.port (port 0: a free port); returns the bound port. Throws
  // std::runtime_error when it cannot bind.
  int bind();
  // Serves until stop(); blocking.
  void listen();
  void stop();
  bool running() const;

  // Every (method, path) served, the data endpoints (data_routes.h) included.
  static const std::vector<std::pair<std::string, std::string>>& routes();

  // Adds the data endpoints (datasets, evaluations, jobs); services must outlive the server.
  void add_data_routes(const DataServices& services);

 private:
  void install_routes();

  ServerConfig config_;
  TableStore& tables_;
  Metrics& metrics_;
  std::unique_ptr<httplib::Server> http_;
  int listen_socket_ = -1;
};

}  // namespace clearsky::server
