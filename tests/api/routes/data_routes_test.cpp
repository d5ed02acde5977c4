// The data route handlers without a server (api/routes/route_handlers.h), on a fresh database:
// every one refuses a query parameter it does not take (GET /v1/jobs/{id} included), ids in
// the path are checked, creations answer with their Location, an upload is read through the
// BodyReader into the spool (and a body above the upload limit is a 413), and a server without
// a database answers 404 no_database; an upload of the broadband irradiance format is checked
// whole before the 202 (400 naming the column, 415 naming Content-Type) and its answers name no
// server path.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "api/evaluation/evaluation_pool.h"
#include "api/imports/import_pool.h"
#include "api/routes/route_handlers.h"
#include "api/routes/route_match.h"
#include "models/registry.h"
#include "storage/schema/migrations.h"
#include "tests/support/synchronous_provider.h"
#include "tests/support/temp_dir.h"
#include "tests/support/test_sky_model.h"
#include "tests/support/zero_filled_zip.h"

namespace clearsky::api {
namespace {

// A body delivered in pieces of at most piece_bytes, as a server would.
class StringBodyReader final : public BodyReader {
 public:
  StringBodyReader(std::string body, std::size_t piece_bytes)
      : body_(std::move(body)), piece_bytes_(piece_bytes) {}
  bool read(const std::function<bool(std::string_view)>& receive) override {
    for (std::size_t at = 0; at < body_.size(); at += piece_bytes_)
      if (!receive(std::string_view(body_).substr(at, piece_bytes_))) return false;
    return true;
  }

 private:
  std::string body_;
  std::size_t piece_bytes_;
};

class DataRouteHandlers : public ::testing::Test {
 protected:
  void SetUp() override {
    storage::open_database(dir.path / "sky.db");
    const auto path = dir.path / "sky.db";
    pool = std::make_unique<EvaluationPool>([path] { return storage::Database::open(path); },
                                            registered_models());
    imports = std::make_unique<ImportPool>([path] { return storage::Database::open(path); });
    data.db_path = path;
    data.upload_dir = dir.path / "uploads";
    data.upload_max_bytes = 1000;
    data.evaluations = pool.get();
    data.imports = imports.get();
    data.models = registered_models();
    data.software_version = "test";
  }

  // The route's handler on method and target ("/v1/jobs/1?x=1"), as the server calls it.
  ApiResponse call(const std::string& method, const std::string& target,
                   const std::string& body = "", BodyReader* reader = nullptr,
                   bool with_data = true, const std::string& content_type = "") {
    ApiRequest request;
    request.method = method;
    const std::size_t question = target.find('?');
    request.path = target.substr(0, question);
    if (question != std::string::npos) {
      std::string query = target.substr(question + 1);
      for (;;) {
        const std::size_t amp = query.find('&');
        const std::string pair = query.substr(0, amp);
        const std::size_t equals = pair.find('=');
        request.query.emplace_back(pair.substr(0, equals), pair.substr(equals + 1));
        if (amp == std::string::npos) break;
        query = query.substr(amp + 1);
      }
    }
    if (!content_type.empty()) request.headers.emplace_back("Content-Type", content_type);
    const RouteMatch match = match_route(method, request.path);
    EXPECT_NE(match.route, nullptr) << method << " " << target;
    if (match.route == nullptr) return {};
    request.route = match.route->pattern;
    request.path_parameters = match.path_parameters;
    request.body = body;
    request.body_reader = reader;
    const ApiContext context{provider, Limits{}, with_data ? &data : nullptr};
    try {
      return match.route->handler(context, request);
    } catch (const ApiError& e) {
      return error_response(e);
    }
  }
  static nlohmann::json json_of(const ApiResponse& r) { return nlohmann::json::parse(r.body); }

  clearsky::testing::TempDir dir;
  clearsky::testing::SynchronousProvider provider{clearsky::testing::test_factories()};
  std::unique_ptr<EvaluationPool> pool;
  std::unique_ptr<ImportPool> imports;
  DataServices data;
};

TEST_F(DataRouteHandlers, EveryRouteRefusesAnUnknownParameter) {
  for (const auto& [method, path] :
       std::vector<std::pair<std::string, std::string>>{{"GET", "/v1/datasets"},
                                                        {"GET", "/v1/datasets/d"},
                                                        {"DELETE", "/v1/datasets/d"},
                                                        {"POST", "/v1/datasets"},
                                                        {"GET", "/v1/imports"},
                                                        {"GET", "/v1/imports/1"},
                                                        {"GET", "/v1/evaluations"},
                                                        {"POST", "/v1/evaluations"},
                                                        {"GET", "/v1/evaluations/1"},
                                                        {"GET", "/v1/evaluations/tickets/1"},
                                                        {"GET", "/v1/jobs"},
                                                        {"POST", "/v1/jobs"},
                                                        {"GET", "/v1/jobs/1"},
                                                        {"DELETE", "/v1/jobs/1"},
                                                        {"POST", "/v1/jobs/1/pause"},
                                                        {"POST", "/v1/jobs/1/resume"},
                                                        {"GET", "/healthz"},
                                                        {"GET", "/v1/models"}}) {
    const ApiResponse r = call(method, path + "?colour=red", "{}");
    EXPECT_EQ(r.status, 400) << method << " " << path << " " << r.body;
    EXPECT_EQ(json_of(r)["error"]["code"], "unknown_parameter") << method << " " << path;
    EXPECT_EQ(json_of(r)["error"]["parameter"], "colour") << method << " " << path;
  }
}

TEST_F(DataRouteHandlers, ReadsAndPathIds) {
  EXPECT_EQ(call("GET", "/v1/datasets").body, "[]");
  EXPECT_EQ(call("GET", "/v1/jobs").body, "[]");
  EXPECT_EQ(call("GET", "/v1/imports?status=queued").body, "[]");
  EXPECT_EQ(call("GET", "/v1/imports?status=lost").status, 400);
  EXPECT_EQ(call("GET", "/v1/jobs/x").status, 400);
  EXPECT_EQ(call("GET", "/v1/jobs/9").status, 404);
  EXPECT_EQ(call("GET", "/v1/datasets/none").status, 404);
  EXPECT_EQ(call("GET", "/v1/datasets/none?samples=maybe").status, 400);
  EXPECT_EQ(json_of(call("GET", "/v1/evaluations/tickets/0"))["error"]["parameter"], "ticket");
  EXPECT_EQ(call("GET", "/v1/evaluations/tickets/5").status, 404);
  EXPECT_EQ(call("GET", "/v1/evaluations?since=never").status, 400);
}

TEST_F(DataRouteHandlers, CreationsAnswerWithTheirLocation) {
  storage::Database db = storage::open_database(data.db_path);
  db.execute("INSERT INTO datasets (name, format, created_utc) VALUES ('d', 'kider2014', 'x')");
  const ApiResponse job =
      call("POST", "/v1/jobs", R"({"name": "n", "schedule": "0 3 * * *", "dataset": "d"})");
  ASSERT_EQ(job.status, 201) << job.body;
  EXPECT_EQ(job.header("Location"), "/v1/jobs/" + std::to_string(json_of(job)["id"].get<int>()));
  EXPECT_EQ(call("GET", std::string(*job.header("Location"))).status, 200);

  const ApiResponse evaluation =
      call("POST", "/v1/evaluations", R"({"models": ["preetham"], "dataset": "d"})");
  ASSERT_EQ(evaluation.status, 202) << evaluation.body;
  EXPECT_EQ(evaluation.header("Location"), json_of(evaluation)["location"]);
  EXPECT_EQ(call("GET", std::string(*evaluation.header("Location"))).status, 200);
}

TEST_F(DataRouteHandlers, UploadsAreReadThroughTheBodyReader) {
  // An archive (the route checks that before it accepts an upload), padded to 600 bytes.
  std::string archive = clearsky::testing::zero_filled_zip_bytes(dir.path, {{"a.txt", 16}});
  archive.resize(600, 'x');
  StringBodyReader small(archive, 64);
  const ApiResponse accepted = call("POST", "/v1/datasets?name=d", "", &small);
  ASSERT_EQ(accepted.status, 202) << accepted.body;
  EXPECT_EQ(json_of(accepted)["upload_bytes"], 600);
  EXPECT_EQ(accepted.header("Location"), json_of(accepted)["location"]);

  StringBodyReader large(std::string(1001, 'x'), 64);
  const ApiResponse refused = call("POST", "/v1/datasets?name=e", "", &large);
  EXPECT_EQ(refused.status, 413);
  EXPECT_EQ(json_of(refused)["error"]["parameter"], "body");

  StringBodyReader empty("", 64);
  EXPECT_EQ(json_of(call("POST", "/v1/datasets?name=e", "", &empty))["error"]["parameter"], "body");
  imports.reset();  // waits for the queued import
}

TEST_F(DataRouteHandlers, BroadbandIrradianceUploadsAreCheckedBefore202) {
  data.upload_max_bytes = 100000;
  const std::string header = "time,latitude,longitude,elevation_m,ghi\n";
  const std::string good = header + "2013-05-27T09:30:00-04:00,42.44,-76.48,250,654.84\n";
  StringBodyReader bad_body(header + "2013-05-27T09:30:00-04:00,42.44,-76.48,250,bright\n", 64);
  const ApiResponse bad =
      call("POST", "/v1/datasets?name=roof&format=irradiance-csv", "", &bad_body, true, "text/csv");
  EXPECT_EQ(bad.status, 400) << bad.body;
  EXPECT_EQ(json_of(bad)["error"]["parameter"], "ghi");
  EXPECT_EQ(bad.body.find(dir.path.string()), std::string::npos) << bad.body;

  StringBodyReader wrong_type_body(good, 64);
  const ApiResponse wrong_type = call("POST", "/v1/datasets?name=roof&format=irradiance-csv", "",
                                      &wrong_type_body, true, "application/json");
  EXPECT_EQ(wrong_type.status, 415);
  EXPECT_EQ(json_of(wrong_type)["error"]["parameter"], "Content-Type");

  StringBodyReader site_body(good, 64);
  EXPECT_EQ(json_of(call("POST", "/v1/datasets?name=roof&format=irradiance-csv&lat=40", "",
                         &site_body, true, "text/csv"))["error"]["parameter"],
            "lat");

  StringBodyReader good_body(good, 64);
  const ApiResponse accepted = call("POST", "/v1/datasets?name=roof&format=irradiance-csv", "",
                                    &good_body, true, "text/csv");
  ASSERT_EQ(accepted.status, 202) << accepted.body;
  // The import's own state, polled until it ends: stopping the pool instead would cancel it if
  // its worker had not yet started it (a loaded machine).
  const std::string location(accepted.header("Location").value_or(""));
  std::string status;
  for (int i = 0; i < 6000 && status != "succeeded" && status != "failed"; ++i) {
    if (i > 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    status = json_of(call("GET", location))["status"].get<std::string>();
  }
  ASSERT_EQ(status, "succeeded") << call("GET", location).body;
  const nlohmann::json shown = json_of(call("GET", "/v1/datasets/roof"));
  EXPECT_EQ(shown["kind"], "broadband_irradiance");
  ASSERT_EQ(shown["irradiance"].size(), 1u);
  EXPECT_EQ(shown["irradiance"][0]["ghi"], 654.84);
}

TEST_F(DataRouteHandlers, WithoutADatabaseTheDataRoutesAnswer404) {
  const ApiResponse r = call("GET", "/v1/datasets", "", nullptr, false);
  EXPECT_EQ(r.status, 404);
  EXPECT_EQ(json_of(r)["error"]["code"], "no_database");
  EXPECT_EQ(json_of(r)["error"]["parameter"], "role");
}

}  // namespace
}  // namespace clearsky::api
