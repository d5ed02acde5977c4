// Route table, error handling, access log and metrics of the HTTP server.
#include "server/http/http_server.h"

#include <httplib.h>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>
#include <sys/socket.h>

#include <chrono>

#include "api/handlers/handlers.h"
#include "api/openapi/openapi_document.h"
#include "api/parse/invalid_parameter.h"
#include "api/skydome/skydome_render.h"
#include "server/http/bounded_task_queue.h"
#include "server/http/request_body.h"

namespace clearsky::server {

namespace {

using Clock = std::chrono::steady_clock;

// Per-request bookkeeping between the pre-routing handler and the logger, which cpp-httplib
// runs on the same worker thread for one request.
struct RequestInfo {
  Clock::time_point start;
  std::string model;
};
thread_local RequestInfo current_request;

const std::vector<std::pair<std::string, std::string>> kRoutes = {
    {"GET", "/healthz"},      {"GET", "/readyz"},       {"GET", "/metrics"},
    {"GET", "/openapi.json"}, {"GET", "/v1/models"},    {"GET", "/v1/sun"},
    {"GET", "/v1/radiance"},  {"POST", "/v1/radiance"}, {"GET", "/v1/irradiance"},
    {"GET", "/v1/rgb"},       {"POST", "/v1/rgb"},      {"GET", "/v1/skydome"},
};

std::string endpoint_label(const std::string& path) {
  for (const auto& [method, route] : kRoutes) {
    if (route == path) return route;
  }
  return "other";
}

void send(httplib::Response& res, const api::ApiResponse& response) {
  res.status = response.status;
  for (const auto& [name, value] : response.headers) res.set_header(name, value);
  res.set_content(response.body, response.content_type);
  current_request.model = response.model_id;
}

api::ApiRequest to_api_request(const httplib::Request& req) {
  api::ApiRequest r;
  r.method = req.method;
  r.path = req.path;
  for (const auto& [name, value] : req.params) r.query.emplace_back(name, value);
  r.body = req.body;
  return r;
}

// Whether path is one of the served POST routes; "{name}" segments match any segment.
bool is_post_route(const std::string& path) {
  const auto segments = [](std::string_view text) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t end = std::min(text.find('/', start), text.size());
      parts.push_back(text.substr(start, end - start));
      start = end + 1;
    }
    return parts;
  };
  const auto requested = segments(path);
  for (const auto& [method, route] : HttpServer::routes()) {
    if (method != "POST") continue;
    const auto pattern = segments(route);
    if (pattern.size() != requested.size()) continue;
    bool match = true;
    for (std::size_t i = 0; i < pattern.size() && match; ++i)
      match = pattern[i] == requested[i] ||
              (pattern[i].size() > 2 && pattern[i].front() == '{' && !requested[i].empty());
    if (match) return true;
  }
  return false;
}

std::shared_ptr<spdlog::logger> access_logger() {
  static std::shared_ptr<spdlog::logger> logger = [] {
    auto existing = spdlog::get("access");
    if (existing) return existing;
    auto created = spdlog::stdout_logger_mt("access");
    created->set_pattern("%v");
    return created;
  }();
  return logger;
}

}  // namespace

const std::vector<std::pair<std::string, std::string>>& HttpServer::routes() {
  static const std::vector<std::pair<std::string, std::string>> all = [] {
    auto routes = kRoutes;
    routes.insert(routes.end(), data_routes().begin(), data_routes().end());
    return routes;
  }();
  return all;
}

void HttpServer::add_data_routes(const DataServices& services) {
  install_data_routes(*http_, services, {config_.payload_max_bytes, config_.body_limit_bytes()});
}

HttpServer::HttpServer(const ServerConfig& config, TableStore& tables, Metrics& metrics)
    : config_(config),
      tables_(tables),
      metrics_(metrics),
      http_(std::make_unique<httplib::Server>()) {
  const unsigned workers = config_.worker_threads();
  const std::size_t queued = config_.max_queued;
  http_->new_task_queue = [workers, queued] { return new BoundedTaskQueue(workers, queued); };
  // The library's one limit is the largest body any route takes (an upload); the other routes
  // apply payload_max_bytes themselves (request_body.h and the pre-routing handler).
  http_->set_payload_max_length(config_.body_limit_bytes());
  http_->set_read_timeout(config_.read_timeout_s, 0);
  http_->set_write_timeout(config_.write_timeout_s, 0);
  http_->set_keep_alive_max_count(config_.keep_alive_max_count);
  http_->set_keep_alive_timeout(config_.keep_alive_timeout_s);
  // cpp-httplib listens with a backlog of 5 (compiled into Debian's library), too short for
  // bursts of connections: the listening socket is kept here and listen(2) is called again
  // with the configured backlog after binding (Linux updates it).
  http_->set_socket_options([this](socket_t socket) {
    httplib::default_socket_options(socket);
    listen_socket_ = socket;
  });
  // Small responses go out at once (no Nagle delay waiting for the client's delayed ACK).
  http_->set_tcp_nodelay(true);
  install_routes();
}

HttpServer::~HttpServer() { stop(); }

int HttpServer::bind() {
  int port = config_.port;
  if (port == 0) {
    port = http_->bind_to_any_port(config_.host);
  } else if (!http_->bind_to_port(config_.host, port)) {
    port = -1;
  }
  if (port <= 0)
    throw std::runtime_error("cannot listen on " + config_.host + ":" +
                             std::to_string(config_.port));
  if (listen_socket_ >= 0 && ::listen(listen_socket_, config_.listen_backlog) != 0) {
    spdlog::warn("listen backlog {} not applied", config_.listen_backlog);
  }
  return port;
}

void HttpServer::listen() { http_->listen_after_bind(); }

void HttpServer::stop() {
  if (http_ && http_->is_running()) http_->stop();
}

bool HttpServer::running() const { return http_->is_running(); }

void HttpServer::install_routes() {
  httplib::Server& s = *http_;
  const api::Limits limits{config_.max_views, config_.max_wavelengths, config_.max_skydome_size};

  // Bodies that no route reads (other methods, unknown POST paths) are refused above the
  // payload limit before they are read: cpp-httplib would buffer them whole up to the upload
  // limit. The connection is closed, since the body is left unread. The POST routes limit
  // their bodies where they read them (read_limited_body; the upload route's spool).
  s.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    current_request = {Clock::now(), {}};
    if (req.method == "POST" && is_post_route(req.path))
      return httplib::Server::HandlerResponse::Unhandled;
    const bool chunked =
        req.get_header_value("Transfer-Encoding").find("chunked") != std::string::npos;
    if (chunked ||
        req.get_header_value<std::uint64_t>("Content-Length") > config_.payload_max_bytes) {
      send(res, api::error_response(api::too_large(
                    "body", "the request body is above the limit of " +
                                std::to_string(config_.payload_max_bytes) + " bytes")));
      res.set_header("Connection", "close");
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });

  // A client that asks before sending its body (Expect: 100-continue, as curl does above
  // 1 MB) learns of a body above the limit of its route at once and never sends it.
  s.set_expect_100_continue_handler([this](const httplib::Request& req, httplib::Response& res) {
    const bool upload = req.method == "POST" && req.path == "/v1/datasets";
    const std::size_t limit = upload ? config_.max_upload_bytes : config_.payload_max_bytes;
    if (req.get_header_value<std::uint64_t>("Content-Length") <= limit) return 100;
    current_request = {Clock::now(), {}};
    send(res, api::error_response(api::too_large(
                  "body", std::string(upload ? "the upload" : "the request body") +
                              " is above the limit of " + std::to_string(limit) + " bytes")));
    // cpp-httplib 0.11.4 writes this answer without its Content-Length (curl then waits for the
    // connection to close, and sends the body meanwhile); the body is never read: close.
    res.set_header("Content-Length", std::to_string(res.body.size()));
    res.set_header("Connection", "close");
    return res.status;
  });

  // The one exception handler: typed API errors keep their status; anything else is a 500
  // whose details go to the log, not to the client.
  s.set_exception_handler([](const httplib::Request& req, httplib::Response& res,
                             std::exception_ptr error) {
    try {
      std::rethrow_exception(error);
    } catch (const api::ApiError& e) {
      send(res, api::error_response(e));
    } catch (const api::InvalidParameter& e) {
      send(res, api::error_response(api::invalid_parameter(e.parameter(), e.message())));
    } catch (const std::exception& e) {
      spdlog::error("{} {}: {}", req.method, req.path, e.what());
      send(res, api::error_response(api::ApiError(500, "internal_error", "", "internal error")));
    } catch (...) {
      spdlog::error("{} {}: unknown exception", req.method, req.path);
      send(res, api::error_response(api::ApiError(500, "internal_error", "", "internal error")));
    }
  });

  // httplib's own errors (no route, payload too large, bad request line) in the same format.
  s.set_error_handler(
      httplib::Server::HandlerWithResponse([](const httplib::Request& req, httplib::Response& res) {
        if (!res.body.empty()) return httplib::Server::HandlerResponse::Unhandled;
        std::string code = "http_error";
        std::string message = "HTTP error " + std::to_string(res.status);
        if (res.status == 404) {
          code = "not_found";
          message = "no route " + req.method + " " + req.path + " (see /openapi.json)";
        } else if (res.status == 413) {
          code = "too_large";
          message = "the request body is above the configured limit";
        }
        const int status = res.status;
        send(res, api::error_response(api::ApiError(status, code, "", message)));
        return httplib::Server::HandlerResponse::Handled;
      }));

  s.set_logger([this](const httplib::Request& req, const httplib::Response& res) {
    const double seconds =
        std::chrono::duration<double>(Clock::now() - current_request.start).count();
    const std::string endpoint = endpoint_label(req.path);
    metrics_.observe_request(endpoint, current_request.model, res.status, seconds);
    access_logger()->info(
        R"({{"remote":"{}","method":"{}","path":"{}","status":{},"bytes":{},"ms":{:.3f},"model":"{}","endpoint":"{}"}})",
        req.remote_addr, req.method, req.path, res.status, res.body.size(), seconds * 1e3,
        current_request.model, endpoint);
  });

  const auto handle =
      [this, limits](api::ApiResponse (*handler)(const api::ApiContext&, const api::ApiRequest&)) {
        return [this, limits, handler](const httplib::Request& req, httplib::Response& res) {
          const api::ApiContext context{tables_, limits};
          send(res, handler(context, to_api_request(req)));
        };
      };
  // POST bodies are read under the payload limit, not buffered by cpp-httplib (whose limit is
  // the upload one).
  const auto handle_post = [this, limits](api::ApiResponse (*handler)(const api::ApiContext&,
                                                                      const api::ApiRequest&)) {
    return [this, limits, handler](const httplib::Request& req, httplib::Response& res,
                                   const httplib::ContentReader& content) {
      api::ApiRequest request = to_api_request(req);
      request.body =
          read_limited_body(req, content, config_.payload_max_bytes, config_.body_limit_bytes());
      const api::ApiContext context{tables_, limits};
      send(res, handler(context, request));
    };
  };
  s.Get("/v1/models", handle(api::get_models));
  s.Get("/v1/sun", handle(api::get_sun));
  s.Get("/v1/radiance", handle(api::radiance));
  s.Post("/v1/radiance", handle_post(api::radiance));
  s.Get("/v1/irradiance", handle(api::irradiance));
  s.Get("/v1/rgb", handle(api::rgb));
  s.Post("/v1/rgb", handle_post(api::rgb));

  // The skydome is checked completely before the response starts; then it is computed band by
  // band and streamed (chunked) from the content provider, which owns the render job.
  s.Get("/v1/skydome", [this, limits](const httplib::Request& req, httplib::Response& res) {
    const api::ApiContext context{tables_, limits};
    auto job = std::make_shared<const api::SkydomeRender>(
        api::prepare_skydome(context, to_api_request(req)));
    current_request.model = job->model_id();
    res.set_header("Content-Disposition", "inline; filename=\"sky.exr\"");
    res.set_chunked_content_provider("image/x-exr", [job](std::size_t, httplib::DataSink& sink) {
      std::size_t unanswered = 0;
      const bool complete = job->write(
          [&sink](const char* data, std::size_t size) {
            return sink.is_writable() && sink.write(data, size);
          },
          0, &unanswered);
      if (unanswered > 0)
        spdlog::warn("skydome {}: {} pixels without a value, written as 0", job->model_id(),
                     unanswered);
      if (complete) sink.done();
      return complete;
    });
  });

  s.Get("/healthz", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(R"({"status":"ok"})", "application/json");
  });
  s.Get("/readyz", [this](const httplib::Request&, httplib::Response& res) {
    nlohmann::json models = nlohmann::json::object();
    for (const ModelFactory& f : tables_.factories()) {
      const api::ModelState state = tables_.default_state(f);
      models[f.descriptor->id] = {{"status", api::to_string(state.status)},
                                  {"progress", api::finite(state.progress)}};
    }
    if (tables_.ready()) {
      res.set_content(nlohmann::json{{"status", "ready"}, {"models", models}}.dump(),
                      "application/json");
      return;
    }
    api::ApiResponse response = api::error_response(
        api::ApiError(503, "not_ready", "", "the default tables of some models are being built",
                      config_.retry_after_s));
    nlohmann::json body = nlohmann::json::parse(response.body);
    body["models"] = models;
    response.body = body.dump();
    send(res, response);
  });
  s.Get("/openapi.json", [](const httplib::Request&, httplib::Response& res) {
    static const std::string document = api::openapi_document().dump(2);
    res.set_content(document, "application/json");
  });
  s.Get("/metrics", [this](const httplib::Request&, httplib::Response& res) {
    res.set_content(metrics_.scrape(tables_.table_bytes()), "text/plain; version=0.0.4");
  });
}

}  // namespace clearsky::server
