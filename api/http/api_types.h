// The transport-free request and response of the API handlers: what the server's HTTP layer
// hands in (method, path, path and query parameters, headers, body) and what it sends back,
// and the context every handler gets. Value types; the route table (api/routes/route_table.h)
// says which handler answers which request (docs/http-api.md).
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "api/datasets/import_roots.h"
#include "api/error/api_error.h"
#include "api/http/body_reader.h"
#include "api/request/sky_request.h"
#include "api/service/model_provider.h"

namespace clearsky::api {

class AnswerMemoryBudget;
class EvaluationPool;
class FitPool;
class ImportPool;

using NameValues = std::vector<std::pair<std::string, std::string>>;

struct ApiRequest {
  std::string method = "GET";
  std::string path;
  NameValues query;
  std::string body;
  // The matched route's pattern ("/v1/jobs/{id}"), naming the endpoint in error messages.
  std::string route = {};
  // The {name} segments of the route's pattern, decoded.
  NameValues path_parameters = {};
  // Header names as received (compared without case by header()).
  NameValues headers = {};
  // Routes that stream their body (BodyPolicy::upload) read it here; body is then empty.
  BodyReader* body_reader = nullptr;
  // The client's network address as the transport saw it (the peer of the connection; behind
  // HAProxy, the proxy's); empty when not a network request. Builds are limited per address.
  std::string client_address = {};

  // The path parameter of that name (std::logic_error when the route has none: a table bug).
  const std::string& path_parameter(std::string_view name) const;
  // The first header of that name, compared without case.
  std::optional<std::string_view> header(std::string_view name) const;
  // "GET /v1/jobs/{id}": the endpoint as error messages name it.
  std::string endpoint() const;
  // The requester of the models this request needs (ModelProvider::model).
  ModelRequester requester() const { return ModelRequester{client_address}; }
};

// Writes bytes to the client as they are produced; false when the client is gone.
using ByteSink = std::function<bool(const char* data, std::size_t size)>;

struct ApiResponse {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
  NameValues headers;
  std::string model_id;  // the model that answered, for metrics; empty when none
  // A streamed body (sent chunked, as it is computed): when set, body is unused. Returns false
  // when the sink refused data (the client left), which stops the computation.
  std::function<bool(const ByteSink& sink)> stream = {};
  // What the answer holds until its last byte was sent or its connection was cut (a body's
  // answer memory reservation, api/http/answer_memory_reservation.h); null: nothing.
  std::shared_ptr<const void> held_until_sent = {};

  // The first header of that name, compared without case.
  std::optional<std::string_view> header(std::string_view name) const;
};

// What the data endpoints (datasets, imports, evaluations, jobs) work with. The pools are
// thread-safe; each request opens its own database connection.
struct DataServices {
  std::filesystem::path db_path;
  std::filesystem::path upload_dir;
  std::size_t upload_max_bytes = std::size_t{1} << 30;
  // Where path= imports may read (none: refused); the byte limits of imports are the
  // ImportPool's (api/imports/import_pool.h).
  ImportRoots import_roots;
  EvaluationPool* evaluations = nullptr;
  ImportPool* imports = nullptr;
  // Atmosphere fits (POST /v1/fits, api/fits/fit_pool.h); null: that route answers 503.
  FitPool* fits = nullptr;
  std::span<const ModelFactory> models;
  std::string software_version;
};

// What handlers need besides the request. Shared by every request: everything in it is
// immutable or thread-safe.
struct ApiContext {
  const ModelProvider& models;
  Limits limits;
  // Null on a server without a database (serve --role query): the data endpoints answer 404
  // no_database naming the role.
  const DataServices* data = nullptr;
  // The Prometheus text of GET /metrics (empty function: 503).
  std::function<std::string()> metrics_text = {};
  // Retry-After of GET /readyz while tables are being built, s.
  int retry_after_s = 5;
  // Where handlers report what the client cannot see (a streamed image's unanswered pixels).
  std::function<void(const std::string& message)> warn = {};
  // True once the server drains before it stops (GET /readyz answers 503 draining); empty:
  // never.
  std::function<bool()> draining = {};
  // Bytes of answer buffers in flight, every worker together (a streamed skydome's band); null:
  // unbounded. Thread-safe.
  AnswerMemoryBudget* answer_memory = nullptr;
  // The quality level of a sky request that does not give `quality` (serve --quality;
  // docs/quality-levels.md).
  QualityLevel default_quality = QualityLevel::standard;
  // Per model id, the background pass over the day's per-sun states: buckets built and their
  // total (the server's DaySunStates, docs/tables-and-memory.md "The day's per-sun states"),
  // shown by GET /readyz; empty: no pass.
  std::function<std::map<std::string, std::pair<std::size_t, std::size_t>>()> day_sun_states = {};
};

// The request's parameters: the query for GET; for POST, the JSON body's scalar members (the
// members named in structured are left to the handler) plus the query.
Parameters request_parameters(const ApiRequest& request,
                              std::initializer_list<std::string_view> structured = {});
// The query parameters only (routes whose body is not a parameter object, or have none).
Parameters query_parameters(const ApiRequest& request);
// The parsed JSON body of a POST (400 when it does not parse).
nlohmann::json request_body(const ApiRequest& request);

ApiResponse json_response(const nlohmann::json& body, int status = 200);
// The same for the data endpoints' ordered documents (members in the order written).
ApiResponse ordered_json_response(const nlohmann::ordered_json& body, int status = 200);
// {"error": {"code", "message", "parameter"}} with the error's status and Retry-After.
ApiResponse error_response(const ApiError& error);
// A JSON number, or std::logic_error for NaN or infinity (NaN never reaches JSON: nlohmann
// would write null without a word).
nlohmann::json finite(double value);

}  // namespace clearsky::api
