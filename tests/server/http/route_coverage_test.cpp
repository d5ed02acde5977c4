// Every row of the route table answers on a real server (with the data endpoints and the
// token): its method on its path, with example inputs, gets an answer of its own — never the
// server's "no route" 404 nor a 405 — and the row's operation is in /openapi.json.
#include <gtest/gtest.h>

#include <map>

#include "api/routes/route_table.h"
#include "tests/server/http/data_server_fixture.h"

namespace clearsky::server {
namespace {

class RouteCoverage : public testing::DataServerFixture {};

// Example inputs per operation: query strings and bodies that the handler accepts.
const std::map<std::string_view, std::pair<std::string, std::string>> kExamples = {
    {"getSun", {"?lat=42.44&lon=-76.48&time=2013-05-27T11:45:00-04:00", ""}},
    {"getRadiance",
     {"?model=testsky&sun_zenith=40&sun_azimuth=100&view_zenith=60&view_azimuth=10", ""}},
    {"postRadiance",
     {"", R"({"model":"testsky","sun_zenith":40,"sun_azimuth":100,"views":[[60,10]]})"}},
    {"getIrradiance", {"?model=testsky&sun_zenith=40&sun_azimuth=100", ""}},
    {"getRgb", {"?model=testsky&sun_zenith=40&sun_azimuth=100&view_zenith=60&view_azimuth=10", ""}},
    {"postRgb", {"", R"({"model":"testsky","sun_zenith":40,"sun_azimuth":100,"views":[[60,10]]})"}},
    {"getSkydome", {"?model=testsky&sun_zenith=40&sun_azimuth=100&size=16", ""}},
    {"getSkyPatches", {"?model=testsky&sun_zenith=40&sun_azimuth=100", ""}},
    {"getIrradianceSeries",
     {"?model=testsky&lat=45&lon=5&start=2024-06-21T10:00:00Z&end=2024-06-21T12:00:00Z", ""}},
    {"importDataset", {"?name=d", "not an archive"}},
    {"createEvaluation", {"", R"({"models": ["preetham"], "dataset": "d"})"}},
    {"createFit", {"", R"({"dataset": "d", "model": "preetham"})"}},
    {"uploadAerosols", {"?name=a", "not an inversion"}},
    {"createJob", {"", R"({"name": "n", "schedule": "0 3 * * *", "dataset": "d"})"}},
};

TEST_F(RouteCoverage, EveryRouteAnswers) {
  start(std::string("t0ken"));
  // Ready tables, so that /readyz and the sky routes answer 200.
  tables->start_default_builds();
  for (int i = 0; i < 400 && !tables->ready(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  {
    storage::Database db = storage::open_database(db_path);
    db.execute("INSERT INTO datasets (name, format, created_utc) VALUES ('d', 'kider2014', 'x')");
  }
  auto c = client("t0ken");
  const auto document = body(c.Get("/openapi.json"));
  for (const api::Route& route : api::routes()) {
    std::string path;
    bool in_parameter = false;
    for (const char ch : route.pattern) {
      if (ch == '{') path += '1';
      in_parameter = (in_parameter || ch == '{') && ch != '}';
      if (!in_parameter && ch != '}') path += ch;
    }
    const auto example = kExamples.find(route.operation_id);
    httplib::Request request;
    request.method = std::string(route.method);
    request.path = path + (example != kExamples.end() ? example->second.first : "");
    if (example != kExamples.end() && !example->second.second.empty()) {
      request.body = example->second.second;
      request.set_header("Content-Type", "application/json");
    }
    const auto r = c.send(request);
    ASSERT_TRUE(r) << route.operation_id;
    EXPECT_NE(r->status, 405) << route.operation_id;
    EXPECT_LT(r->status, 500) << route.operation_id << " " << r->body;
    if (r->status == 404) {
      EXPECT_NE(body(r)["error"]["code"], "not_found") << route.operation_id << " " << r->body;
    }
    std::string method(route.method);
    for (char& ch : method) ch = static_cast<char>(std::tolower(ch));
    EXPECT_EQ(document["paths"][std::string(route.pattern)][method]["operationId"],
              route.operation_id);
  }
}

}  // namespace
}  // namespace clearsky::server
