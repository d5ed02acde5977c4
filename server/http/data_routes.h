// The data endpoints of HTTP API v1 (docs/http-api.md) on the server's cpp-httplib instance, next
// to the query endpoints of http_server.cpp and under its exception handler, error format and
// limits: /v1/datasets, /v1/imports, /v1/evaluations and /v1/jobs, calling the transport-free
// handlers of api/datasets, api/imports, api/evaluation and api/jobs. Writes (POST, DELETE) need
// the bearer token (server/auth/write_auth.h; 401 carries WWW-Authenticate: Bearer) and are logged
// on "audit" with their outcome. Uploads are streamed to a spool file (api/datasets/upload_spool.h)
// under upload_max_bytes, then imported on the ImportPool (202 + Location /v1/imports/{id}); other
// bodies are read under the payload limit (request_body.h). Each request opens its own database
// connection (WAL: readers do not wait for writers); imports and evaluations run on their pools,
// never on HTTP workers.
// Thread-safety: DataServices is shared by the HTTP workers; its members are thread-safe.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "api/evaluation/evaluation_pool.h"
#include "api/imports/import_pool.h"
#include "server/auth/write_auth.h"

namespace httplib {
class Server;
}

namespace clearsky::server {

struct DataServices {
  std::filesystem::path db_path;
  std::filesystem::path upload_dir;
  std::size_t upload_max_bytes = std::size_t{1} << 30;
  api::EvaluationPool* pool = nullptr;
  api::ImportPool* imports = nullptr;
  const WriteAuthorizer* auth = nullptr;
  std::span<const ModelFactory> models;
  std::string software_version;
};

// The body limits of the routes other than the upload: kept up to payload, drained up to drain.
struct BodyLimits {
  std::size_t payload_bytes = 8u << 20;
  std::size_t drain_bytes = std::size_t{1} << 30;
};

void install_data_routes(httplib::Server& server, const DataServices& services,
                         const BodyLimits& limits);

// Every (method, path) install_data_routes serves, with OpenAPI-style {parameters}.
const std::vector<std::pair<std::string, std::string>>& data_routes();

}  // namespace clearsky::server
