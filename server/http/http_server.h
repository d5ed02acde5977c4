// The HTTP boundary (docs/conventions.md "One HTTP boundary"): cpp-httplib serving the route
// table of api/routes/route_table.h, in one place (docs/http-api.md "From socket to handler").
// - before a body is read (pre-routing): the route is found (404, or 405 with Allow), OPTIONS
//   and CORS preflights are answered, bodies a route does not read are refused above the
//   payload limit, and the bearer token of a write route is checked (401/403);
// - each route's transport-free handler runs with the server's ApiContext; its body is read by
//   the route's body policy (JSON under the payload limit, uploads streamed), its answer gets
//   the cache headers of its policy (ETag, 304) and CORS headers, and a streamed answer is
//   sent chunked;
// - one exception handler (ApiError -> its status; anything else, caught with catch (...),
//   -> 500) and one error format {"error": {"code", "message", "parameter"}}, also for
//   httplib's own errors (413 payload, bad request line);
// - limits from ServerConfig: worker threads, bounded queue, payload, timeouts, keep-alive;
// - the browser viewer's static files at / (viewer_files.h), when a viewer folder is given;
// - a structured access log line per request (spdlog logger "access"), Prometheus metrics
//   labelled by route pattern, and an "audit" line for every write with its outcome.
// Thread-safety: start()/stop() from one controlling thread; requests run on the workers.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "api/http/answer_memory_budget.h"
#include "api/http/api_types.h"
#include "api/http/cors.h"
#include "server/auth/write_auth.h"
#include "server/config/server_config.h"
#include "server/http/viewer_files.h"
#include "server/metrics/metrics.h"
#include "server/tables/table_store.h"

namespace httplib {
class Server;
class ContentReader;
struct Request;
struct Response;
}  // namespace httplib

namespace clearsky::server {

class ConnectionServer;

class HttpServer {
 public:
  HttpServer(const ServerConfig& config, TableStore& tables, Metrics& metrics);
  ~HttpServer();

  // The services of the data endpoints (datasets, imports, evaluations, jobs) and the bearer
  // token of the write routes; both must outlive the server. Call before bind(). Without
  // them (a query replica) the data endpoints, writes included, answer 404 no_database.
  void add_data_services(const api::DataServices& services, const WriteAuthorizer& auth);
  // The progress /readyz shows of the background pass over the day's per-sun states
  // (api::ApiContext::day_sun_states). Call before bind().
  void set_day_sun_states(
      std::function<std::map<std::string, std::pair<std::size_t, std::size_t>>()> progress) {
    context_.day_sun_states = std::move(progress);
  }

  // Binds config.host:config.port (port 0: a free port); returns the bound port. Throws
  // std::runtime_error when it cannot bind.
  int bind();
  // Serves until stop(); blocking. Returns once every connection has ended.
  void listen();
  // Closes the listening socket: idle connections end, requests in flight finish.
  void stop();
  bool running() const;

  // The first step of a graceful drain (docs/deploy.md "Graceful drain"): /readyz answers 503
  // (code draining) and every answer closes its connection; the server still accepts until
  // stop(). Thread-safe.
  void begin_drain();
  // Ends every connection still open (the drain's time is up); returns how many. Thread-safe.
  std::size_t cut_connections();

 private:
  void install();
  // The matched route's answer (pre-routing found it); content is null for methods whose
  // body cpp-httplib reads itself.
  void answer(const httplib::Request& req, httplib::Response& res,
              const httplib::ContentReader* content);
  void send(const httplib::Request& req, httplib::Response& res, api::ApiResponse response);

  ServerConfig config_;
  TableStore& tables_;
  Metrics& metrics_;
  api::CorsPolicy cors_;
  ViewerFiles viewer_;
  api::DataServices data_;
  // Before context_, which points to it.
  api::AnswerMemoryBudget answer_memory_;
  api::ApiContext context_;
  WriteAuthorizer no_token_{std::nullopt};
  const WriteAuthorizer* auth_ = &no_token_;
  std::unique_ptr<ConnectionServer> http_;
  int listen_socket_ = -1;
};

}  // namespace clearsky::server
