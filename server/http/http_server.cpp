// The route table on cpp-httplib: pre-routing checks, the generic installation of the
// routes, error handling, access log and metrics of the HTTP server.
#include "server/http/http_server.h"

#include <fmt/compile.h>
#include <httplib.h>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>
#include <sys/socket.h>

#include <chrono>
#include <set>

#include "api/http/cache_policy.h"
#include "api/routes/data_access.h"
#include "api/routes/route_match.h"
#include "server/http/connection_server.h"
#include "server/http/header_text.h"
#include "server/http/request_body.h"
#include "storage/sqlite/database.h"

namespace clearsky::server {

namespace {

using Clock = std::chrono::steady_clock;
using HandlerResponse = httplib::Server::HandlerResponse;

// Per-request bookkeeping from the pre-routing handler (or the Expect handler) to the route's
// handler and the logger, which cpp-httplib runs on the same worker thread for one request.
struct RequestInfo {
  Clock::time_point start;
  std::string model;
  api::RouteMatch match;
  // The metrics and access-log label: the route's pattern ("other" for unknown paths), so
  // that the label set stays bounded.
  std::string_view endpoint = "other";
  // The request's body is (partly) unread: the answer ends the connection.
  bool unread_body = false;
  // The request line and headers were read whole (pre-routing ran).
  bool head_read = false;
};
thread_local RequestInfo current_request;

void begin_request(const httplib::Request& req) {
  current_request = {Clock::now(), {},    api::match_route(req.method, req.path),
                     "other",      false, true};
  if (current_request.match.path_known()) current_request.endpoint = current_request.match.pattern;
}

api::ApiRequest to_api_request(const httplib::Request& req) {
  api::ApiRequest r;
  r.method = req.method;
  r.path = req.path;
  r.client_address = req.remote_addr;
  for (const auto& [name, value] : req.params) r.query.emplace_back(name, value);
  for (const auto& [name, value] : req.headers) r.headers.emplace_back(name, value);
  const api::RouteMatch& match = current_request.match;
  if (match.route != nullptr) {
    r.route = match.route->pattern;
    r.path_parameters = match.path_parameters;
  }
  return r;
}

bool chunked(const httplib::Request& req) {
  return req.get_header_value("Transfer-Encoding").find("chunked") != std::string::npos;
}

// A body follows the head, unread so far.
bool body_pending(const httplib::Request& req) {
  return chunked(req) || req.get_header_value<std::uint64_t>("Content-Length") > 0;
}

api::ApiError body_too_large(std::size_t limit_bytes, const char* what) {
  return api::too_large("body", std::string(what) + " is above the limit of " +
                                    std::to_string(limit_bytes) + " bytes");
}

// The refusal of a write route's request without the right token (401 with
// WWW-Authenticate, or 403 when writes are disabled); logged on "audit".
api::ApiResponse refuse_write(const WriteAuthorizer& auth, const httplib::Request& req) {
  try {
    auth.authorize(req.method, req.path, req.get_header_value("Authorization"), req.remote_addr);
  } catch (const api::ApiError& e) {
    api::ApiResponse response = api::error_response(e);
    if (e.status() == 401) response.headers.emplace_back("WWW-Authenticate", "Bearer");
    return response;
  }
  throw std::logic_error("refuse_write called for an authorised request");
}

// A write's handler with its outcome on the "audit" logger, whatever happens.
api::ApiResponse run_write(const api::Route& route, const api::ApiContext& context,
                           const api::ApiRequest& request, const httplib::Request& req) {
  try {
    api::ApiResponse response = route.handler(context, request);
    audit_logger()->info("write done: {} {} from {} -> {}", req.method, req.path, req.remote_addr,
                         response.status);
    return response;
  } catch (const api::ApiError& e) {
    audit_logger()->info("write failed: {} {} from {} -> {} {}", req.method, req.path,
                         req.remote_addr, e.status(), e.code());
    throw;
  } catch (...) {
    audit_logger()->info("write failed: {} {} from {} -> 500", req.method, req.path,
                         req.remote_addr);
    throw;
  }
}

// Sends res's body, then ends the connection: the refused request's body is still unread, and
// cpp-httplib would read it as the next request. A content provider that stops after writing
// everything makes it close the connection once the answer is out (cpp-httplib 0.11.4).
void close_after_answer(httplib::Response& res) {
  res.set_header("Connection", "close");
  if (res.body.empty()) return;
  auto body = std::make_shared<const std::string>(std::move(res.body));
  res.body.clear();
  const std::string type = res.get_header_value("Content-Type");
  res.headers.erase("Content-Type");
  res.set_content_provider(body->size(), type,
                           [body](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                             sink.write(body->data() + offset, length);
                             return false;
                           });
}

// cpp-httplib's own refusals (it answers them before any handler runs, with an empty body), in
// the API's format, naming the part of the request and the limit at fault.
api::ApiError library_refusal(const httplib::Request& req, int status, std::size_t body_limit) {
  if (status == 414)
    return api::ApiError::about(414, "uri_too_long", "uri",
                                "the request target is longer than " +
                                    std::to_string(CPPHTTPLIB_REQUEST_URI_MAX_LENGTH) + " bytes");
  if (status == 413) return body_too_large(body_limit, "the request body");
  if (status == 404)
    return api::ApiError(404, "not_found", "path",
                         "no route " + req.method + " " + req.path + " (see /openapi.json)");
  if (status == 416)
    return api::ApiError::about(416, "range_not_satisfiable", "Range",
                                "not a byte range of this answer");
  if (status == 400) {
    if (current_request.head_read)
      return api::ApiError::about(400, "bad_request", "body",
                                  "the body does not match its Content-Length or chunked coding");
    if (!req.method.empty() && (req.version == "HTTP/1.1" || req.version == "HTTP/1.0"))
      return api::ApiError::about(400, "bad_request", "headers",
                                  "a header line is malformed, or longer than " +
                                      std::to_string(CPPHTTPLIB_HEADER_MAX_LENGTH) + " bytes");
    return api::ApiError::about(400, "bad_request", "request_line",
                                "not METHOD TARGET HTTP/1.1 (RFC 9112 section 3)");
  }
  return api::ApiError::about(status, "http_error", "request",
                              "HTTP error " + std::to_string(status));
}

// What the client is told of an exception that is not an API error: a database write that found
// the disk full is 507 naming the disk, anything else 500 (the details go to the log only).
api::ApiError unexpected_error(const std::exception& e) {
  const auto* sqlite = dynamic_cast<const storage::SqliteError*>(&e);
  if (sqlite != nullptr && sqlite->disk_full())
    return api::insufficient_storage("writing the database");
  return api::ApiError(500, "internal_error", "", "internal error");
}

// The answer when composing an error answer failed itself (nothing here depends on the
// request), so that every request is answered and its connection released.
void answer_last_resort(httplib::Response& res) noexcept {
  static constexpr const char* kBody =
      R"({"error":{"code":"internal_error","message":"internal error","parameter":"request"}})";
  try {
    res.status = 500;
    res.set_header("Cache-Control", "no-store");
    res.set_content(kBody, "application/json");
  } catch (...) {
    res.status = 500;
  }
}

const std::shared_ptr<spdlog::logger>& access_logger() {
  static std::shared_ptr<spdlog::logger> logger = [] {
    auto existing = spdlog::get("access");
    if (existing) return existing;
    auto created = spdlog::stdout_logger_mt("access");
    created->set_pattern("%v");
    return created;
  }();
  return logger;
}

// The time limits of a connection (docs/deployment.md "Limits in the server").
ConnectionLimits connection_limits(const ServerConfig& config) {
  using std::chrono::seconds;
  ConnectionLimits limits;
  limits.read_timeout = seconds(config.read_timeout_s);
  limits.write_timeout = seconds(config.write_timeout_s);
  limits.keep_alive_timeout = seconds(config.keep_alive_timeout_s);
  limits.head_timeout = seconds(config.request_head_timeout_s);
  limits.min_send_rate_bytes_per_s = config.min_send_rate_bytes;
  limits.send_rate_grace = seconds(config.send_rate_grace_s);
  return limits;
}

// Workers grow on demand up to the cap; connections beyond it wait in a bounded queue.
ElasticTaskQueue::Options worker_pool(const ServerConfig& config) {
  config.check_connection_slots();
  ElasticTaskQueue::Options pool;
  pool.max_workers = config.worker_threads();
  pool.max_queued = config.max_queued;
  return pool;
}

}  // namespace

HttpServer::HttpServer(const ServerConfig& config, TableStore& tables, Metrics& metrics)
    : config_(config),
      tables_(tables),
      metrics_(metrics),
      cors_(config.cors_origins),
      viewer_(config.viewer_dir),
      answer_memory_(config.answer_memory_bytes),
      context_{tables,
               {config.max_views, config.max_wavelengths, config.max_skydome_size},
               nullptr,
               [this] {
                 metrics_.observe_answer_memory(answer_memory_.reserved_bytes(),
                                                answer_memory_.limit_bytes());
                 return metrics_.scrape(tables_.table_bytes());
               },
               config.retry_after_s,
               [](const std::string& message) { spdlog::warn("{}", message); },
               [this] { return http_->draining(); },
               &answer_memory_,
               parse_quality_level(config.quality).value_or(QualityLevel::standard)},
      http_(std::make_unique<ConnectionServer>(connection_limits(config), worker_pool(config))) {
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
  install();
}

HttpServer::~HttpServer() { stop(); }

void HttpServer::add_data_services(const api::DataServices& services, const WriteAuthorizer& auth) {
  data_ = services;
  context_.data = &data_;
  auth_ = &auth;
}

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

void HttpServer::begin_drain() { http_->begin_drain(); }

std::size_t HttpServer::cut_connections() { return http_->cut_connections(); }

void HttpServer::send(const httplib::Request& req, httplib::Response& res,
                      api::ApiResponse response) {
  // Answers without a cache policy (errors, refusals) are never stored.
  if (!response.header("Cache-Control")) response.headers.emplace_back("Cache-Control", "no-store");
  if (cors_.enabled()) {
    const std::string origin = req.get_header_value("Origin");
    cors_.add_headers(
        req.has_header("Origin") ? std::optional<std::string_view>(origin) : std::nullopt,
        response);
  }
  res.status = response.status;
  // What cpp-httplib's set_header() does (header_text.h), the texts moved rather than copied.
  for (auto& [name, value] : response.headers) {
    if (holds_line_break(name) || holds_line_break(value)) continue;
    res.headers.emplace(std::move(name), std::move(value));
  }
  current_request.model = response.model_id;
  if (response.stream) {
    res.set_chunked_content_provider(
        response.content_type,
        [stream = std::move(response.stream)](std::size_t, httplib::DataSink& sink) {
          const bool complete = stream([&sink](const char* data, std::size_t size) {
            return sink.is_writable() && sink.write(data, size);
          });
          if (complete) sink.done();
          return complete;
        });
  } else if (response.held_until_sent && response.status != 204 && response.status != 304) {
    // A body that holds memory of the answer budget: a content provider of its known length
    // keeps the reservation until cpp-httplib has written the last byte (or the connection was
    // cut) and the response is destroyed.
    auto body = std::make_shared<const std::string>(std::move(response.body));
    res.set_content_provider(body->size(), response.content_type,
                             [body, held = std::move(response.held_until_sent)](
                                 std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                               return sink.write(body->data() + offset, length);
                             });
  } else if (response.status != 204 && response.status != 304) {
    // What set_content() does, but moving the body: cpp-httplib's set_content copies it.
    res.body = std::move(response.body);
    res.headers.erase("Content-Type");
    res.set_header("Content-Type", response.content_type);
  }
  if (current_request.unread_body) close_after_answer(res);
}

void HttpServer::answer(const httplib::Request& req, httplib::Response& res,
                        const httplib::ContentReader* content) {
  const api::Route* route = current_request.match.route;
  // A viewer file listed at start but gone since (viewer_files.h): cpp-httplib found no file.
  if (route == nullptr && current_request.endpoint == "viewer")
    throw api::ApiError(404, "not_found", "path", "no viewer file " + req.path);
  if (route == nullptr) throw std::logic_error("a request reached dispatch without its route");
  api::ApiRequest request = to_api_request(req);
  std::optional<UploadBodyReader> upload;
  if (content != nullptr && route->body == api::BodyPolicy::upload) {
    upload.emplace(req, *content, config_.max_upload_bytes);
    request.body_reader = &*upload;
    // Until the handler has read it (a request refused for its parameters is not).
    current_request.unread_body = body_pending(req);
  } else if (content != nullptr) {
    // JSON bodies are kept; a body a route does not take is drained under the same limit.
    std::string body =
        read_limited_body(req, *content, config_.payload_max_bytes, config_.body_limit_bytes());
    if (route->body == api::BodyPolicy::json) request.body = std::move(body);
  } else if (route->body == api::BodyPolicy::json) {
    request.body = req.body;
  }
  const auto run = [&] {
    try {
      return route->needs_token ? run_write(*route, context_, request, req)
                                : route->handler(context_, request);
    } catch (...) {
      if (upload && upload->complete()) current_request.unread_body = false;
      throw;
    }
  };
  api::ApiResponse response = run();
  if (upload && upload->complete()) current_request.unread_body = false;
  api::apply_caching(route->caching, request, response);
  send(req, res, std::move(response));
}

void HttpServer::install() {
  httplib::Server& s = *http_;

  // The browser viewer at / (docs/viewer.md): the listed files of its folder; the pre-routing
  // handler lets only those through to the mount point.
  if (viewer_.enabled()) {
    // One mount per cache policy (viewer_files.h), the assets' first: cpp-httplib tries them in
    // order and sets their headers on GET and HEAD alike. (Without an assets/ folder the first
    // mount is refused, and nothing is lost.)
    const auto headers = [](const char* url_path) {
      return httplib::Headers{{"Cache-Control", ViewerFiles::cache_control(url_path)},
                              {"Content-Security-Policy", ViewerFiles::content_security_policy()},
                              {"X-Content-Type-Options", "nosniff"}};
    };
    s.set_mount_point("/assets/", viewer_.dir() + "/assets", headers("/assets/"));
    s.set_mount_point("/", viewer_.dir(), headers("/"));
  }

  // Everything decided from the head, before any body is read: the route, OPTIONS, the body a
  // route does not read, the token. A refusal leaves a pending body unread: the connection is
  // then closed (the client must not send the body as the next request).
  s.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    begin_request(req);
    const api::RouteMatch& match = current_request.match;
    const bool is_chunked = chunked(req);
    const bool pending = is_chunked || req.get_header_value<std::uint64_t>("Content-Length") > 0;
    const auto refuse = [&](api::ApiResponse response) {
      current_request.unread_body = pending;
      send(req, res, std::move(response));
      return HandlerResponse::Handled;
    };
    if (req.method == "OPTIONS" && match.path_known())
      return refuse(cors_.options(to_api_request(req), api::allow_header(match)));
    // POST routes read (or drain) their body under their own limit; other bodies would be
    // buffered whole by cpp-httplib up to the upload limit: refused above the payload limit.
    const bool reads_body = match.route != nullptr && match.route->method == "POST";
    if (!reads_body &&
        (is_chunked || (pending && req.get_header_value<std::uint64_t>("Content-Length") >
                                       config_.payload_max_bytes))) {
      api::ApiResponse response =
          api::error_response(body_too_large(config_.payload_max_bytes, "the request body"));
      response.headers.emplace_back("Connection", "close");
      return refuse(std::move(response));
    }
    // The viewer's files (viewer_files.h): cpp-httplib's mount point answers them.
    if (!match.path_known() && (req.method == "GET" || req.method == "HEAD") &&
        viewer_.serves(req.path)) {
      current_request.endpoint = "viewer";
      return HandlerResponse::Unhandled;
    }
    if (!match.path_known())
      return refuse(api::error_response(
          api::ApiError(404, "not_found", "path",
                        "no route " + req.method + " " + req.path + " (see /openapi.json)")));
    if (match.route == nullptr) {
      api::ApiResponse response = api::error_response(
          api::ApiError(405, "method_not_allowed", "method",
                        req.method + " is not served on " + req.path + " (see /openapi.json)"));
      response.headers.emplace_back("Allow", api::allow_header(match));
      return refuse(std::move(response));
    }
    // Every write route is a data route: a server without a database (a query replica) says
    // so before it asks for a token it could not use.
    if (match.route->needs_token && context_.data == nullptr)
      return refuse(api::error_response(api::no_database()));
    if (match.route->needs_token && !auth_->allows(req.get_header_value("Authorization")))
      return refuse(refuse_write(*auth_, req));
    // cpp-httplib reads no body of a GET (or HEAD): a small one left there ends the connection.
    current_request.unread_body = match.route->method == "GET" && pending;
    return HandlerResponse::Unhandled;
  });

  // A client that asks before sending its body (Expect: 100-continue, as curl does above
  // 1 MB) learns at once of a body above the limit of its route, or of a missing token, and
  // never sends the body.
  s.set_expect_100_continue_handler([this](const httplib::Request& req, httplib::Response& res) {
    const api::RouteMatch match = api::match_route(req.method, req.path);
    const bool upload = match.route != nullptr && match.route->body == api::BodyPolicy::upload;
    const std::size_t limit = upload ? config_.max_upload_bytes : config_.payload_max_bytes;
    api::ApiResponse refusal;
    if (req.get_header_value<std::uint64_t>("Content-Length") > limit) {
      refusal =
          api::error_response(body_too_large(limit, upload ? "the upload" : "the request body"));
    } else if (match.route != nullptr && match.route->needs_token && context_.data == nullptr) {
      refusal = api::error_response(api::no_database());
    } else if (match.route != nullptr && match.route->needs_token &&
               !auth_->allows(req.get_header_value("Authorization"))) {
      refusal = refuse_write(*auth_, req);
    } else {
      return 100;
    }
    begin_request(req);
    send(req, res, std::move(refusal));
    // cpp-httplib 0.11.4 writes this answer without its Content-Length (curl then waits for the
    // connection to close, and sends the body meanwhile); the body is never read: close.
    res.set_header("Content-Length", std::to_string(res.body.size()));
    res.set_header("Connection", "close");
    return res.status;
  });

  // The one exception handler: typed API errors keep their status; anything else is a 500
  // (507 for a full disk, unexpected_error) whose details go to the log, not to the client. It never throws: an exception leaving it
  // would leave the request unanswered and its connection open (cpp-httplib 0.11.4).
  s.set_exception_handler(
      [this](const httplib::Request& req, httplib::Response& res, std::exception_ptr error) {
        try {
          try {
            std::rethrow_exception(error);
          } catch (const api::ApiError& e) {
            send(req, res, api::error_response(e));
          } catch (const std::exception& e) {
            spdlog::error("{} {}: {}", req.method, req.path, e.what());
            send(req, res, api::error_response(unexpected_error(e)));
          } catch (...) {
            spdlog::error("{} {}: unknown exception", req.method, req.path);
            send(req, res,
                 api::error_response(api::ApiError(500, "internal_error", "", "internal error")));
          }
        } catch (...) {
          answer_last_resort(res);
        }
      });

  // httplib's own errors (URI too long, bad request line or header, payload too large) in the
  // same format; never throws (as the exception handler).
  s.set_error_handler(httplib::Server::HandlerWithResponse(
      [this](const httplib::Request& req, httplib::Response& res) {
        // Answers of this server (send() gives each a Cache-Control) are left as they are.
        if (!res.body.empty() || res.has_header("Cache-Control")) return HandlerResponse::Unhandled;
        try {
          send(req, res,
               api::error_response(library_refusal(req, res.status, config_.body_limit_bytes())));
        } catch (...) {
          answer_last_resort(res);
        }
        return HandlerResponse::Handled;
      }));

  s.set_logger([this](const httplib::Request& req, const httplib::Response& res) {
    const double seconds =
        std::chrono::duration<double>(Clock::now() - current_request.start).count();
    const std::string endpoint(current_request.endpoint);
    metrics_.observe_request(endpoint, current_request.model, res.status, seconds);
    const std::shared_ptr<spdlog::logger>& log = access_logger();
    if (log->should_log(spdlog::level::info)) {
      // The line's layout compiled (FMT_COMPILE) rather than parsed on every request.
      fmt::memory_buffer line;
      fmt::format_to(
          std::back_inserter(line),
          FMT_COMPILE(
              R"({{"remote":"{}","method":"{}","path":"{}","status":{},"bytes":{},"ms":{:.3f},"model":"{}","endpoint":"{}"}})"),
          req.remote_addr, req.method, req.path, res.status, res.body.size(), seconds * 1e3,
          current_request.model, endpoint);
      log->info(std::string_view(line.data(), line.size()));
    }
    // A request that never reaches pre-routing (a bad request line) must not inherit this one.
    current_request = {Clock::now(), {}, {}, "other", false, false};
  });

  // The routes: pre-routing matched each request against the table, so each method the table
  // uses has one catch-all handler that runs the matched route.
  std::set<std::string_view> methods;
  for (const api::Route& route : api::routes()) methods.insert(route.method);
  const auto plain = [this](const httplib::Request& req, httplib::Response& res) {
    answer(req, res, nullptr);
  };
  const auto with_body = [this](const httplib::Request& req, httplib::Response& res,
                                const httplib::ContentReader& content) {
    answer(req, res, &content);
  };
  for (const std::string_view method : methods) {
    if (method == "GET")
      s.Get(".*", plain);
    else if (method == "DELETE")
      s.Delete(".*", plain);
    else if (method == "POST")
      s.Post(".*", with_body);
    else
      throw std::logic_error("the route table uses a method the server cannot install: " +
                             std::string(method));
  }
}

}  // namespace clearsky::server
