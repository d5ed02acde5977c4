// /v1/datasets, /v1/evaluations and /v1/jobs over HTTP (data_routes.h).
#include "server/http/data_routes.h"

#include <httplib.h>
#include <spdlog/spdlog.h>

#include <chrono>

#include "api/datasets/datasets_api.h"
#include "api/datasets/upload_spool.h"
#include "api/evaluation/evaluations_api.h"
#include "api/http/api_types.h"
#include "api/imports/imports_api.h"
#include "api/jobs/jobs_api.h"
#include "api/paging/list_page.h"
#include "server/http/request_body.h"
#include "storage/sqlite/database.h"

namespace clearsky::server {
namespace {

const std::vector<std::pair<std::string, std::string>> kDataRoutes = {
    {"GET", "/v1/datasets"},
    {"POST", "/v1/datasets"},
    {"GET", "/v1/datasets/{name}"},
    {"DELETE", "/v1/datasets/{name}"},
    {"GET", "/v1/imports"},
    {"GET", "/v1/imports/{id}"},
    {"GET", "/v1/evaluations"},
    {"POST", "/v1/evaluations"},
    {"GET", "/v1/evaluations/{id}"},
    {"GET", "/v1/evaluations/tickets/{ticket}"},
    {"GET", "/v1/jobs"},
    {"POST", "/v1/jobs"},
    {"GET", "/v1/jobs/{id}"},
    {"DELETE", "/v1/jobs/{id}"},
    {"POST", "/v1/jobs/{id}/pause"},
    {"POST", "/v1/jobs/{id}/resume"},
};

double now_unix_s() {
  using namespace std::chrono;
  return duration<double>(system_clock::now().time_since_epoch()).count();
}

void send_json(httplib::Response& res, const nlohmann::ordered_json& body, int status = 200) {
  res.status = status;
  res.set_content(body.dump(), "application/json");
}

std::vector<std::pair<std::string, std::string>> query_of(const httplib::Request& req) {
  return {req.params.begin(), req.params.end()};
}

// A page of a list: the bare array, and the next page in a Link header (api/paging/list_page.h).
void send_page(const httplib::Request& req, httplib::Response& res, const api::ListPage& page) {
  if (page.next_cursor)
    res.set_header("Link", api::next_page_link(req.path, query_of(req),
                                               api::parse_page_request(query_of(req)).limit,
                                               *page.next_cursor));
  send_json(res, page.items);
}

std::string query_value(const httplib::Request& req, const char* name) {
  return req.has_param(name) ? req.get_param_value(name) : std::string();
}

// Refuses query parameters the endpoint does not take (the API's rule for every endpoint). Not
// applied to JSON bodies: cpp-httplib adds a form-encoded body's fields to the parameters.
void only_parameters(const httplib::Request& req, std::initializer_list<std::string_view> known,
                     const std::string& endpoint) {
  for (const auto& [name, value] : req.params) {
    bool ok = false;
    for (std::string_view k : known) ok = ok || name == k;
    if (!ok) throw api::unknown_parameter(name, endpoint);
  }
}

bool flag(const httplib::Request& req, const char* name) {
  const std::string v = query_value(req, name);
  if (v.empty() || v == "false" || v == "0") return false;
  if (v == "true" || v == "1") return true;
  throw api::invalid_parameter(name, "\"" + v + "\" is not true or false");
}

storage::Database connect(const DataServices& s) { return storage::Database::open(s.db_path); }

// A write: authorised first, then run; its outcome is logged whatever happens.
template <typename Action>
void write(const DataServices& s, const httplib::Request& req, httplib::Response& res,
           Action&& action) {
  try {
    s.auth->authorize(req.method, req.path, req.get_header_value("Authorization"), req.remote_addr);
  } catch (const api::ApiError& e) {
    if (e.status() != 401) throw;
    const api::ApiResponse r = api::error_response(e);
    res.status = r.status;
    res.set_header("WWW-Authenticate", "Bearer");
    res.set_content(r.body, r.content_type);
    return;
  }
  try {
    action();
    audit_logger()->info("write done: {} {} from {} -> {}", req.method, req.path, req.remote_addr,
                         res.status);
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

}  // namespace

const std::vector<std::pair<std::string, std::string>>& data_routes() { return kDataRoutes; }

void install_data_routes(httplib::Server& server, const DataServices& services,
                         const BodyLimits& limits) {
  const DataServices* s = &services;
  const auto read_body = [limits](const httplib::Request& req,
                                  const httplib::ContentReader& content) {
    return read_limited_body(req, content, limits.payload_bytes, limits.drain_bytes);
  };

  server.Get("/v1/datasets", [s](const httplib::Request& req, httplib::Response& res) {
    storage::Database db = connect(*s);
    send_page(req, res, api::list_datasets(db, query_of(req)));
  });
  server.Get(R"(/v1/datasets/([^/]+))", [s](const httplib::Request& req, httplib::Response& res) {
    only_parameters(req, {"samples", "capture"}, "GET /v1/datasets/{name}");
    api::ShowDatasetOptions options;
    options.samples = flag(req, "samples");
    if (req.has_param("capture")) options.capture = query_value(req, "capture");
    storage::Database db = connect(*s);
    send_json(res, api::show_dataset(db, req.matches[1], options));
  });
  server.Delete(R"(/v1/datasets/([^/]+))",
                [s](const httplib::Request& req, httplib::Response& res) {
                  write(*s, req, res, [&] {
                    only_parameters(req, {}, "DELETE /v1/datasets/{name}");
                    storage::Database db = connect(*s);
                    send_json(res, api::delete_dataset(db, req.matches[1]));
                  });
                });
  // The body is the archive, spooled to disk as it arrives; or no body and path=SERVER_PATH
  // (an archive or folder on the server: the token holder is the administrator). Checked here
  // (parameters, format, path, size), then imported on the ImportPool: 202 with the import's
  // state and its Location.
  server.Post("/v1/datasets", [s](const httplib::Request& req, httplib::Response& res,
                                  const httplib::ContentReader& content) {
    write(*s, req, res, [&] {
      only_parameters(req, {"name", "format", "path"}, "POST /v1/datasets");
      storage::NewImport what;
      what.dataset = query_value(req, "name");
      if (what.dataset.empty()) throw api::missing_parameter("name", "the dataset to import into");
      what.format = req.has_param("format") ? query_value(req, "format") : "kider";
      api::check_import_format(what.format);
      auto spool = std::make_unique<api::UploadSpool>(s->upload_dir, s->upload_max_bytes);
      std::exception_ptr failure;
      const bool read = content([&](const char* data, std::size_t size) {
        try {
          spool->append(std::string_view(data, size));
          return true;
        } catch (...) {
          failure = std::current_exception();
          return false;
        }
      });
      if (failure) std::rethrow_exception(failure);
      // cpp-httplib skips, without calling the receiver, a body above its payload limit.
      if (!read) {
        if (req.get_header_value<std::uint64_t>("Content-Length") > s->upload_max_bytes)
          throw api::too_large("body", "the upload is above the limit of " +
                                           std::to_string(s->upload_max_bytes) + " bytes");
        throw api::ApiError(400, "invalid_body", "body", "body: the upload could not be read");
      }
      std::filesystem::path source;
      if (req.has_param("path")) {
        if (spool->size_bytes() > 0) throw api::conflicting_parameters("path", "an uploaded body");
        spool.reset();
        what.source = "path";
        what.path = query_value(req, "path");
        std::error_code error;
        if (!std::filesystem::exists(what.path, error))
          throw api::invalid_parameter("path", "no file or folder " + what.path + " on the server");
        source = what.path;
      } else {
        if (spool->size_bytes() == 0)
          throw api::missing_parameter("body", "the archive (.7z, zip or tar), or path=");
        what.source = "upload";
        what.upload_bytes = static_cast<std::int64_t>(spool->size_bytes());
        source = spool->finish();
      }
      if (s->imports == nullptr)
        throw api::ApiError(503, "imports_unavailable", "", "this server runs no import workers");
      storage::Database db = connect(*s);
      const std::int64_t id = s->imports->submit(db, what, source, std::move(spool));
      res.set_header("Location", api::import_location(id));
      send_json(res, api::show_import(db, s->imports, id), 202);
    });
  });

  server.Get("/v1/imports", [s](const httplib::Request& req, httplib::Response& res) {
    storage::Database db = connect(*s);
    send_page(req, res, api::list_imports(db, s->imports, query_of(req)));
  });
  server.Get(R"(/v1/imports/([^/]+))", [s](const httplib::Request& req, httplib::Response& res) {
    only_parameters(req, {}, "GET /v1/imports/{id}");
    storage::Database db = connect(*s);
    send_json(res, api::show_import(db, s->imports, api::parse_id(req.matches[1], "id")));
  });

  server.Get("/v1/evaluations", [s](const httplib::Request& req, httplib::Response& res) {
    const api::EvaluationFilter filter = api::parse_evaluation_filter(query_of(req));
    const api::PageRequest page = api::parse_page_request(query_of(req));
    storage::Database db = connect(*s);
    send_page(req, res, api::list_evaluations(db, filter, page));
  });
  server.Get(R"(/v1/evaluations/(\d+))", [s](const httplib::Request& req, httplib::Response& res) {
    std::vector<std::pair<std::string, std::string>> query(req.params.begin(), req.params.end());
    const api::ShowEvaluationOptions options = api::parse_show_evaluation_options(query);
    storage::Database db = connect(*s);
    send_json(res, api::show_evaluation(db, api::parse_id(req.matches[1], "id"), options));
  });
  server.Get(R"(/v1/evaluations/tickets/([^/]+))",
             [s](const httplib::Request& req, httplib::Response& res) {
               const auto ticket = s->pool->ticket(api::parse_id(req.matches[1], "ticket"));
               if (!ticket)
                 throw api::ApiError(404, "unknown_ticket", "ticket",
                                     "ticket: no evaluation ticket " + std::string(req.matches[1]));
               send_json(res, api::ticket_to_json(*ticket));
             });
  server.Post("/v1/evaluations", [s, read_body](const httplib::Request& req, httplib::Response& res,
                                                const httplib::ContentReader& content) {
    write(*s, req, res, [&] {
      const std::string text = read_body(req, content);
      storage::Database db = connect(*s);
      const std::int64_t ticket =
          s->pool->submit(api::parse_evaluation_request(db, text, s->models, s->software_version));
      nlohmann::ordered_json body = api::ticket_to_json(*s->pool->ticket(ticket));
      body["location"] = api::ticket_location(ticket);
      res.set_header("Location", api::ticket_location(ticket));
      send_json(res, body, 202);
    });
  });

  server.Get("/v1/jobs", [s](const httplib::Request& req, httplib::Response& res) {
    storage::Database db = connect(*s);
    send_page(req, res, api::list_jobs(db, query_of(req)));
  });
  server.Get(R"(/v1/jobs/([^/]+))", [s](const httplib::Request& req, httplib::Response& res) {
    storage::Database db = connect(*s);
    send_json(res, api::show_job(db, api::parse_id(req.matches[1], "id")));
  });
  server.Post("/v1/jobs", [s, read_body](const httplib::Request& req, httplib::Response& res,
                                         const httplib::ContentReader& content) {
    write(*s, req, res, [&] {
      const std::string text = read_body(req, content);
      storage::Database db = connect(*s);
      const api::CreatedResource job = api::create_job(db, text, s->models, now_unix_s());
      res.set_header("Location", job.location);
      send_json(res, job.body, 201);
    });
  });
  server.Delete(R"(/v1/jobs/([^/]+))", [s](const httplib::Request& req, httplib::Response& res) {
    write(*s, req, res, [&] {
      storage::Database db = connect(*s);
      send_json(res, api::delete_job(db, api::parse_id(req.matches[1], "id")));
    });
  });
  server.Post(R"(/v1/jobs/([^/]+)/(pause|resume))",
              [s, read_body](const httplib::Request& req, httplib::Response& res,
                             const httplib::ContentReader& content) {
                write(*s, req, res, [&] {
                  read_body(req, content);
                  storage::Database db = connect(*s);
                  const std::int64_t id = api::parse_id(req.matches[1], "id");
                  send_json(res, req.matches[2] == "pause" ? api::pause_job(db, id)
                                                           : api::resume_job(db, id, now_unix_s()));
                });
              });
}

}  // namespace clearsky::server
