// The route table and its matching (api/routes/route_table.h, route_match.h): one row per
// (method, pattern) and per operationId, writes need the token and are never stored, a
// body is read only by the routes that take one; paths match segment by segment with path
// parameters, a known path with another method gives its methods (405 with Allow), HEAD is
// answered by GET.
#include "api/routes/route_table.h"

#include <gtest/gtest.h>

#include <set>

#include "api/routes/route_match.h"

namespace clearsky::api {
namespace {

TEST(RouteTable, OneRowPerRouteAndOperation) {
  std::set<std::pair<std::string_view, std::string_view>> routes_seen;
  std::set<std::string_view> ids;
  for (const Route& route : routes()) {
    EXPECT_TRUE(routes_seen.emplace(route.method, route.pattern).second) << route.pattern;
    EXPECT_TRUE(ids.insert(route.operation_id).second) << route.operation_id;
    EXPECT_NE(route.handler, nullptr) << route.operation_id;
    // A row matches its own pattern (with any value in its parameters) and nothing earlier.
    std::string path;
    bool in_parameter = false;
    for (const char c : route.pattern) {
      if (c == '{') path += '7';
      in_parameter = (in_parameter || c == '{') && c != '}';
      if (!in_parameter && c != '}') path += c;
    }
    const RouteMatch match = match_route(route.method, path);
    EXPECT_EQ(match.route, &route) << path;
  }
  EXPECT_EQ(routes().size(), 36u);
}

TEST(RouteTable, WritesNeedTheTokenAndAreNeverStored) {
  for (const Route& route : routes()) {
    const bool write = route.method == "POST" || route.method == "DELETE";
    const bool data =
        route.pattern.starts_with("/v1/datasets") || route.pattern.starts_with("/v1/imports") ||
        route.pattern.starts_with("/v1/evaluations") || route.pattern.starts_with("/v1/fits") ||
        route.pattern.starts_with("/v1/aerosols") || route.pattern.starts_with("/v1/jobs");
    EXPECT_EQ(route.needs_token, write && data) << route.operation_id;
    if (write || data) {
      EXPECT_EQ(route.caching, Caching::no_store) << route.operation_id;
    }
    if (route.method != "POST") {
      EXPECT_EQ(route.body, BodyPolicy::none) << route.operation_id;
    }
  }
}

TEST(RouteMatch, PathParametersAndMethods) {
  const RouteMatch job = match_route("GET", "/v1/jobs/42");
  ASSERT_NE(job.route, nullptr);
  EXPECT_EQ(job.route->operation_id, "getJob");
  EXPECT_EQ(job.path_parameters, (NameValues{{"id", "42"}}));
  EXPECT_EQ(job.pattern, "/v1/jobs/{id}");

  const RouteMatch pause = match_route("POST", "/v1/jobs/42/pause");
  ASSERT_NE(pause.route, nullptr);
  EXPECT_EQ(pause.route->operation_id, "pauseJob");

  const RouteMatch ticket = match_route("GET", "/v1/evaluations/tickets/3");
  ASSERT_NE(ticket.route, nullptr);
  EXPECT_EQ(ticket.route->operation_id, "getEvaluationTicket");
  EXPECT_EQ(ticket.path_parameters, (NameValues{{"ticket", "3"}}));

  const RouteMatch head = match_route("HEAD", "/v1/models");
  ASSERT_NE(head.route, nullptr);
  EXPECT_EQ(head.route->operation_id, "listModels");
}

TEST(RouteMatch, WrongMethodGivesThePathsMethods) {
  const RouteMatch put = match_route("PUT", "/v1/jobs/7");
  EXPECT_EQ(put.route, nullptr);
  EXPECT_TRUE(put.path_known());
  EXPECT_EQ(allow_header(put), "GET, HEAD, DELETE, OPTIONS");
  EXPECT_EQ(allow_header(match_route("DELETE", "/v1/radiance")), "GET, HEAD, POST, OPTIONS");
  EXPECT_EQ(allow_header(match_route("GET", "/v1/jobs/7/pause")), "POST, OPTIONS");
}

TEST(RouteMatch, UnknownPaths) {
  for (const char* path : {"/", "", "/v1", "/v1/jobs/", "/v1/jobs//pause", "/v1/jobs/1/stop",
                           "/healthz/", "/v1/models/x", "v1/models", "/V1/models"}) {
    const RouteMatch match = match_route("GET", path);
    EXPECT_FALSE(match.path_known()) << path;
    EXPECT_EQ(match.route, nullptr) << path;
  }
}

}  // namespace
}  // namespace clearsky::api
