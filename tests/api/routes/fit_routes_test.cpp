// The fit route handlers without a server (api/routes/fit_routes.cpp, docs/fits.md "Over
// HTTP"), on a fresh database with a dataset Preetham made: POST /v1/fits refuses with a 400
// naming the member (unknown member, unknown model, a parameter that cannot be fitted, bad
// bounds, an unknown capture label) and a 404 for an unknown dataset, before anything is recorded; an accepted fit
// answers 202 with its Location, is queued, runs on the pool and is listed; GET /v1/fits/{id}
// answers 404 unknown_fit and 400 for a bad id; without a database the routes answer 404.
#include <gtest/gtest.h>

#include "api/fits/fit_pool.h"
#include "api/routes/route_handlers.h"
#include "api/routes/route_match.h"
#include "models/registry.h"
#include "storage/schema/migrations.h"
#include "tests/support/model_made_dataset.h"
#include "tests/support/synchronous_provider.h"
#include "tests/support/temp_dir.h"
#include "tests/support/test_sky_model.h"

namespace clearsky::api {
namespace {

class FitRouteHandlers : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto path = dir.path / "sky.db";
    storage::Database db = storage::open_database(path);
    ModelConfig truth;
    truth.atmosphere.turbidity = 3.4;
    clearsky::testing::store_model_made_dataset(db, "made", "preetham", truth,
                                                {{30.0, 120.0}, {45.0, 100.0}});
    fits = std::make_unique<FitPool>([path] { return storage::Database::open(path); });
    data.db_path = path;
    data.fits = fits.get();
    data.models = registered_models();
    data.software_version = "test";
  }

  // The route's handler on method and target ("/v1/fits/1?x=1"), as the server calls it.
  ApiResponse call(const std::string& method, const std::string& target,
                   const std::string& body = "", bool with_data = true) {
    ApiRequest request;
    request.method = method;
    const std::size_t question = target.find('?');
    request.path = target.substr(0, question);
    if (question != std::string::npos) {
      const std::string query = target.substr(question + 1);
      const std::size_t equals = query.find('=');
      request.query.emplace_back(query.substr(0, equals), query.substr(equals + 1));
    }
    const RouteMatch match = match_route(method, request.path);
    EXPECT_NE(match.route, nullptr) << method << " " << target;
    if (match.route == nullptr) return {};
    request.route = match.route->pattern;
    request.path_parameters = match.path_parameters;
    request.body = body;
    const ApiContext context{provider, Limits{}, with_data ? &data : nullptr};
    try {
      return match.route->handler(context, request);
    } catch (const ApiError& e) {
      return error_response(e);
    }
  }
  static nlohmann::json json_of(const ApiResponse& r) { return nlohmann::json::parse(r.body); }
  // The error's status and parameter.
  std::pair<int, std::string> refusal(const std::string& body) {
    const ApiResponse r = call("POST", "/v1/fits", body);
    if (r.status < 400) return {r.status, ""};
    return {r.status, json_of(r)["error"]["parameter"].get<std::string>()};
  }

  clearsky::testing::TempDir dir;
  clearsky::testing::SynchronousProvider provider{clearsky::testing::test_factories()};
  std::unique_ptr<FitPool> fits;
  DataServices data;
};

using Refusal = std::pair<int, std::string>;

TEST_F(FitRouteHandlers, RefusalsNameTheMember) {
  EXPECT_EQ(refusal(R"({"model": "preetham"})"), Refusal(400, "dataset"));
  EXPECT_EQ(refusal(R"({"dataset": "made"})"), Refusal(400, "model"));
  EXPECT_EQ(refusal(R"({"dataset": "made", "model": "preetham", "colour": 1})"),
            Refusal(400, "colour"));
  EXPECT_EQ(refusal(R"({"dataset": "made", "model": "nishita2042"})"), Refusal(400, "model"));
  EXPECT_EQ(refusal(R"({"dataset": "made", "model": "preetham", "free": ["alpha"]})"),
            Refusal(400, "free"));
  EXPECT_EQ(refusal(R"({"dataset": "made", "model": "preetham", "free": "turbidity"})"),
            Refusal(400, "free"));
  EXPECT_EQ(refusal(R"({"dataset": "made", "model": "preetham", "bounds": {"turbidity": [6, 2]}})"),
            Refusal(400, "bounds"));
  EXPECT_EQ(
      refusal(R"({"dataset": "made", "model": "preetham", "bounds": {"turbidity": [1, 99]}})"),
      Refusal(400, "bounds"));
  EXPECT_EQ(refusal(R"({"dataset": "made", "model": "preetham", "grid": [0]})"),
            Refusal(400, "grid"));
  EXPECT_EQ(refusal(R"({"dataset": "made", "model": "preetham", "per_capture": "yes"})"),
            Refusal(400, "per_capture"));
  EXPECT_EQ(refusal(R"({"dataset": "made", "model": "preetham", "max_evaluations": -1})"),
            Refusal(400, "max_evaluations"));
  EXPECT_EQ(
      refusal(R"({"dataset": "made", "model": "preetham", "parameters": {"turbidity": "x"}})"),
      Refusal(400, "turbidity"));
  EXPECT_EQ(refusal(R"({"dataset": "made", "model": "preetham", "captures": ["made 0", "x"]})"),
            Refusal(400, "captures"));
  EXPECT_EQ(refusal("[1]"), Refusal(400, "body"));
  const ApiResponse unknown = call("POST", "/v1/fits", R"({"dataset": "none", "model": "hosek"})");
  EXPECT_EQ(unknown.status, 404);
  EXPECT_EQ(json_of(unknown)["error"]["code"], "unknown_dataset");
  // Nothing was recorded.
  EXPECT_EQ(call("GET", "/v1/fits").body, "[]");
}

TEST_F(FitRouteHandlers, AcceptedFitsRunInTheBackground) {
  const ApiResponse accepted = call(
      "POST", "/v1/fits",
      R"({"dataset": "made", "model": "preetham", "bounds": {"turbidity": [2, 6]}, "grid": [9]})");
  ASSERT_EQ(accepted.status, 202) << accepted.body;
  const nlohmann::json queued = json_of(accepted);
  EXPECT_EQ(accepted.header("Location"), "/v1/fits/" + std::to_string(queued["id"].get<int>()));
  EXPECT_EQ(queued["location"], accepted.header("Location"));
  EXPECT_EQ(queued["dataset"], "made");
  EXPECT_EQ(queued["model"], "preetham");
  EXPECT_FALSE(queued.contains("values"));
  fits->wait_idle();
  const ApiResponse done = call("GET", std::string(*accepted.header("Location")));
  ASSERT_EQ(done.status, 200) << done.body;
  const nlohmann::json fit = json_of(done);
  EXPECT_EQ(fit["status"], "succeeded") << done.body;
  EXPECT_EQ(fit["progress"], 1.0);
  EXPECT_EQ(fit["free_parameters"][0]["name"], "turbidity");
  EXPECT_EQ(fit["free_parameters"][0]["grid_points"], 9);
  EXPECT_FALSE(fit.contains("history"));
  EXPECT_TRUE(json_of(call("GET", std::string(*accepted.header("Location")) + "?history=true"))
                  .contains("history"));
  const nlohmann::json list = json_of(call("GET", "/v1/fits"));
  ASSERT_EQ(list.size(), 1u);
  EXPECT_EQ(list[0]["id"], fit["id"]);
  EXPECT_EQ(list[0]["values"], fit["values"]);
}

TEST_F(FitRouteHandlers, ReadsAndPathIds) {
  const ApiResponse missing = call("GET", "/v1/fits/9");
  EXPECT_EQ(missing.status, 404);
  EXPECT_EQ(json_of(missing)["error"]["code"], "unknown_fit");
  EXPECT_EQ(json_of(call("GET", "/v1/fits/x"))["error"]["parameter"], "id");
  EXPECT_EQ(json_of(call("GET", "/v1/fits/9?history=maybe"))["error"]["parameter"], "history");
  EXPECT_EQ(json_of(call("GET", "/v1/fits?limit=0"))["error"]["parameter"], "limit");
  for (const auto& [method, path] : std::vector<std::pair<std::string, std::string>>{
           {"GET", "/v1/fits"}, {"POST", "/v1/fits"}, {"GET", "/v1/fits/1"}}) {
    const ApiResponse r = call(method, path + "?colour=red", "{}");
    EXPECT_EQ(r.status, 400) << method << " " << path;
    EXPECT_EQ(json_of(r)["error"]["parameter"], "colour") << method << " " << path;
    const ApiResponse replica = call(method, path, "{}", false);
    EXPECT_EQ(replica.status, 404) << method << " " << path;
    EXPECT_EQ(json_of(replica)["error"]["code"], "no_database") << method << " " << path;
  }
}

}  // namespace
}  // namespace clearsky::api
