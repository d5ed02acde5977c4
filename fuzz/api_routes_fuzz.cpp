// Every route of the HTTP API (api/routes/route_table.h) through its transport-free handler,
// as the server calls it, on the cheap analytic models only (Preetham and Hosek: no table
// precomputation) and a temporary SQLite database. docs/fuzzing.md describes the input and the
// invariants; in short, an input is a small HTTP request as text:
//
//   METHOD PATH[?QUERY]        query percent-decoded as the server does ('+' is a space)
//   Name: value                optional header lines
//                              an empty line, then the body (a JSON body, or an upload)
//
// Invariants: nothing but an ApiError leaves a handler; no 500; an error is JSON
// {"error": {"code", "message", "parameter"}} with a code, and a parameter wherever the status
// is about the request's content (400, 413, 422); a 2xx JSON body parses, holds no null on the
// sky routes, and its radiances, irradiances and luminances are >= 0; a CSV body holds no
// non-finite number.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <string_view>

#include "api/evaluation/evaluation_pool.h"
#include "api/imports/import_pool.h"
#include "api/routes/route_match.h"
#include "fuzz/support/fuzz_check.h"
#include "fuzz/support/scratch_dir.h"
#include "models/registry.h"
#include "storage/schema/migrations.h"
#include "tests/support/synchronous_provider.h"

namespace clearsky::fuzz {
namespace {

std::vector<ModelFactory> analytic_models() {
  std::vector<ModelFactory> models;
  for (const char* id : {"preetham", "hosek"}) models.push_back(*find_model(id));
  return models;
}

// Everything the handlers share, built once per process. Requests that write (jobs, imports)
// accumulate in the database, as on a server; it is started afresh now and then so that it
// stays small.
struct Service {
  ScratchDir scratch{"api_routes"};
  std::vector<ModelFactory> models = analytic_models();
  clearsky::testing::SynchronousProvider provider{models};
  std::filesystem::path db_path;
  std::unique_ptr<api::EvaluationPool> evaluations;
  std::unique_ptr<api::ImportPool> imports;
  api::DataServices data;
  std::unique_ptr<api::ApiContext> context;
  int requests = 0;

  Service() { reset(); }

  void reset() {
    evaluations.reset();
    imports.reset();
    std::filesystem::remove_all(scratch.path / "data");
    std::filesystem::create_directories(scratch.path / "data");
    db_path = scratch.path / "data" / "sky.db";
    storage::open_database(db_path);
    const auto open = [path = db_path] { return storage::Database::open(path); };
    evaluations = std::make_unique<api::EvaluationPool>(open, models);
    imports = std::make_unique<api::ImportPool>(open);
    data.db_path = db_path;
    data.upload_dir = scratch.path / "data" / "uploads";
    data.upload_max_bytes = 1 << 20;
    std::filesystem::create_directories(scratch.path / "data" / "server_files");
    data.import_roots = api::ImportRoots({(scratch.path / "data" / "server_files").string()});
    data.evaluations = evaluations.get();
    data.imports = imports.get();
    data.models = models;
    data.software_version = "fuzz";
    // Small limits keep each input quick (a skydome of at most 32 x 32 pixels).
    context.reset(new api::ApiContext{provider, api::Limits{64, 64, 32}, &data});
  }

  // The background work a request started (an import, an evaluation) ends before the next
  // input, so that each input is judged on its own.
  void settle() {
    imports->wait_idle();
    evaluations->wait_idle();
    if (++requests % 5000 == 0) reset();
  }
};

Service& service() {
  static Service s;
  return s;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string percent_decoded(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '+') {
      out.push_back(' ');
    } else if (text[i] == '%' && i + 2 < text.size() && hex_digit(text[i + 1]) >= 0 &&
               hex_digit(text[i + 2]) >= 0) {
      out.push_back(static_cast<char>(hex_digit(text[i + 1]) * 16 + hex_digit(text[i + 2])));
      i += 2;
    } else {
      out.push_back(text[i]);
    }
  }
  return out;
}

api::NameValues query_of(std::string_view query) {
  api::NameValues values;
  while (!query.empty()) {
    const std::size_t amp = query.find('&');
    const std::string_view pair = query.substr(0, amp);
    query = amp == std::string_view::npos ? std::string_view{} : query.substr(amp + 1);
    if (pair.empty()) continue;
    const std::size_t equals = pair.find('=');
    std::string name = percent_decoded(pair.substr(0, equals));
    // cpp-httplib drops a parameter without a name: handlers never see one.
    if (name.empty()) continue;
    values.emplace_back(std::move(name), equals == std::string_view::npos
                                             ? std::string()
                                             : percent_decoded(pair.substr(equals + 1)));
  }
  return values;
}

// A server-side import path stays inside the scratch folder, the service's one import root (which
// the route enforces as well, api/datasets/import_roots.h): the fuzzer must not import the
// machine's file system.
std::string sandboxed_path(const std::filesystem::path& root, std::string path) {
  for (std::size_t at = path.find(".."); at != std::string::npos; at = path.find("..", at))
    path.replace(at, 2, "__");
  return (root / "data" / "server_files" / path).string();
}

bool sky_route(std::string_view pattern) {
  return pattern == "/v1/radiance" || pattern == "/v1/irradiance" || pattern == "/v1/rgb" ||
         pattern == "/v1/sun";
}

// Members whose numbers the API promises non-negative (docs/http-api.md): spectral radiance,
// irradiance, illuminance and luminance, wavelengths.
bool non_negative_member(std::string_view key) {
  return key == "radiance" || key == "wavelengths_nm" || key == "illuminance_lx" ||
         key == "luminance_cd_m2" || key.ends_with("_w_m2") || key.ends_with("_w_m2_nm");
}

// The members a sky answer may leave null, each only with the member that says why
// (docs/http-api.md): the broadband figures when the answer names why the model cannot go
// broadband (broadband_unavailable), and the quality level's error when the request overrode
// one of the level's options (quality_overridden), and the sunrise and sunset of a polar day
// or night (day). Any other null could be a value that was not computed.
std::set<std::string> explained_null_members(const nlohmann::json& body) {
  std::set<std::string> out;
  if (!body.is_object()) return out;
  const auto unavailable = body.find("broadband_unavailable");
  if (unavailable != body.end() && unavailable->is_string() &&
      !unavailable->get<std::string>().empty()) {
    out.insert("broadband");
    out.insert("broadband_irradiance_w_m2");
  }
  const auto overridden = body.find("quality_overridden");
  if (overridden != body.end() && !overridden->empty()) out.insert("quality_error");
  // /v1/sun: no sunrise or sunset on a polar day or night, which "day" names.
  const auto day = body.find("day");
  if (day != body.end() && day->is_string() && day->get<std::string>() != "normal") {
    out.insert("sunrise");
    out.insert("sunset");
  }
  return out;
}

void check_json_numbers(const nlohmann::json& value, bool sky, bool non_negative,
                        const std::string& where, const std::string& input,
                        const std::set<std::string>& nullable = {}, bool explained = false) {
  if (value.is_null()) check(!sky || explained, "null in a sky answer at " + where, input);
  if (value.is_number()) {
    const double x = value.get<double>();
    check(std::isfinite(x), "non-finite number at " + where, input);
    check(!non_negative || x >= 0.0, "negative number at " + where, input);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i)
      check_json_numbers(value[i], sky, non_negative, where + "[" + std::to_string(i) + "]", input,
                         nullable);
  } else if (value.is_object()) {
    for (const auto& [key, member] : value.items())
      check_json_numbers(member, sky, non_negative || non_negative_member(key), where + "." + key,
                         input, nullable, nullable.count(key) > 0);
  }
}

void check_csv(const std::string& body, const std::string& input) {
  std::size_t start = 0;
  while (start < body.size()) {
    std::size_t end = body.find_first_of(",\n", start);
    if (end == std::string::npos) end = body.size();
    const std::string cell = body.substr(start, end - start);
    char* rest = nullptr;
    const double x = std::strtod(cell.c_str(), &rest);
    if (!cell.empty() && rest != cell.c_str() && *rest == '\0')
      check(std::isfinite(x), "non-finite CSV cell " + cell, input);
    start = end + 1;
  }
}

void check_response(const api::ApiResponse& response, std::string_view pattern,
                    const std::string& input) {
  check(response.status != 500, "500 answer: " + response.body, input);
  check(response.status >= 200 && response.status < 600,
        "status out of range: " + std::to_string(response.status), input);
  if (response.status >= 400) {
    nlohmann::json body;
    try {
      body = nlohmann::json::parse(response.body);
    } catch (const nlohmann::json::exception& e) {
      fail(std::string("error body is not JSON: ") + e.what(), input);
    }
    check(body.contains("error") && body["error"].is_object(), "error body without error", input);
    const nlohmann::json& error = body["error"];
    check(error.contains("code") && error["code"].is_string() &&
              !error["code"].get<std::string>().empty(),
          "error without a code: " + response.body, input);
    check(error.contains("message") && error["message"].is_string(),
          "error without a message: " + response.body, input);
    check(error.contains("parameter"), "error without a parameter member: " + response.body, input);
    // Known bug being fixed on its own (docs/fuzzing.md "Known bugs excluded"): a body that is
    // not JSON, or not an object, is refused naming no parameter (it will name "body").
    const bool known_unnamed_body = error["code"] == "invalid_body";
    const bool about_content =
        (response.status == 400 || response.status == 413 || response.status == 422) &&
        !known_unnamed_body;
    check(!about_content || error["parameter"].is_string(),
          "refusal naming no parameter: " + response.body, input);
    return;
  }
  if (response.status >= 300 || response.status == 204) return;
  if (response.content_type.starts_with("application/json")) {
    nlohmann::json body;
    try {
      body = nlohmann::json::parse(response.body);
    } catch (const nlohmann::json::exception& e) {
      fail(std::string("2xx body is not JSON: ") + e.what(), input);
    }
    check_json_numbers(body, sky_route(pattern), false, "body", input,
                       explained_null_members(body));
  } else if (response.content_type.starts_with("text/csv")) {
    check_csv(response.body, input);
  }
}

}  // namespace
}  // namespace clearsky::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace clearsky;
  using namespace clearsky::fuzz;
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::string_view rest = input;
  const auto next_line = [&rest] {
    const std::size_t end = rest.find('\n');
    std::string_view line = rest.substr(0, end);
    rest = end == std::string_view::npos ? std::string_view{} : rest.substr(end + 1);
    if (line.ends_with('\r')) line.remove_suffix(1);
    return line;
  };
  const std::string_view request_line = next_line();
  const std::size_t space = request_line.find(' ');
  if (space == std::string_view::npos) return 0;
  api::ApiRequest request;
  request.method = std::string(request_line.substr(0, space));
  const std::string_view target = request_line.substr(space + 1);
  const std::size_t question = target.find('?');
  request.path = std::string(target.substr(0, question));
  if (question != std::string_view::npos) request.query = query_of(target.substr(question + 1));
  for (std::string_view line = next_line(); !line.empty(); line = next_line()) {
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos) continue;
    std::string_view value = line.substr(colon + 1);
    while (value.starts_with(' ')) value.remove_prefix(1);
    request.headers.emplace_back(std::string(line.substr(0, colon)), std::string(value));
  }
  request.body = std::string(rest);

  const api::RouteMatch match = api::match_route(request.method, request.path);
  // 404 and 405 are answered by the server before any handler (server/http/http_server.cpp).
  if (match.route == nullptr) return 0;
  request.route = std::string(match.route->pattern);
  request.path_parameters = match.path_parameters;
  // Routes without a body never see one (the server drains or refuses it).
  if (match.route->body == api::BodyPolicy::none) request.body.clear();
  Service& s = service();
  if (match.route->operation_id == "importDataset")
    for (auto& [name, value] : request.query)
      if (name == "path") value = sandboxed_path(s.scratch.path, value);

  api::ApiResponse response;
  try {
    response = match.route->handler(*s.context, request);
    if (response.stream) {
      std::string streamed;
      response.stream([&streamed](const char* bytes, std::size_t n) {
        streamed.append(bytes, n);
        return true;
      });
      response.body = std::move(streamed);
    }
  } catch (const api::ApiError& e) {
    response = api::error_response(e);
  } catch (const std::exception& e) {
    fail(std::string("a handler threw something else than ApiError (a 500): ") + e.what(), input);
  }
  s.settle();
  check_response(response, match.route->pattern, input);
  return 0;
}
