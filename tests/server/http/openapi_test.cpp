// /openapi.json is generated from the route table: it parses, is OpenAPI 3 with servers,
// every route of the table is described under its pattern and method with its operationId
// (and an operation doc exists for it), nothing is described that is not a route, and every
// $ref resolves.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "api/openapi/operation_docs.h"
#include "api/routes/route_table.h"
#include "tests/server/http/server_fixture.h"

namespace clearsky::server {
namespace {

class OpenApiTest : public testing::ServerFixture {};

void collect_refs(const nlohmann::json& j, std::vector<std::string>& refs) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) {
      if (k == "$ref" && v.is_string()) refs.push_back(v.get<std::string>());
      collect_refs(v, refs);
    }
  } else if (j.is_array()) {
    for (const auto& v : j) collect_refs(v, refs);
  }
}

std::string lower(std::string_view method) {
  std::string text(method);
  for (char& ch : text) ch = static_cast<char>(std::tolower(ch));
  return text;
}

TEST_F(OpenApiTest, DescribesEveryRouteAndNothingElse) {
  auto c = client();
  const auto r = c.Get("/openapi.json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200);
  const auto doc = nlohmann::json::parse(r->body);
  EXPECT_EQ(doc["openapi"].get<std::string>().substr(0, 2), "3.");
  ASSERT_TRUE(doc["info"].contains("title"));
  ASSERT_TRUE(doc["servers"].is_array());
  EXPECT_EQ(doc["servers"][0]["url"], "/");
  for (const api::Route& route : api::routes()) {
    const std::string path(route.pattern);
    ASSERT_NE(api::operation_doc(route.operation_id), nullptr) << route.operation_id;
    ASSERT_TRUE(doc["paths"].contains(path)) << path;
    ASSERT_TRUE(doc["paths"][path].contains(lower(route.method))) << route.method << " " << path;
    const auto& op = doc["paths"][path][lower(route.method)];
    EXPECT_EQ(op["operationId"], route.operation_id) << path;
    EXPECT_TRUE(op.contains("summary")) << path;
    EXPECT_TRUE(op["responses"].contains("200") || op["responses"].contains("201") ||
                op["responses"].contains("202"))
        << path;
  }
  // Nothing is described that is not a route.
  std::set<std::string> operation_ids;
  for (const auto& [path, operations] : doc["paths"].items()) {
    for (const auto& [method, op] : operations.items()) {
      bool served = false;
      for (const api::Route& route : api::routes())
        served = served || (route.pattern == path && lower(route.method) == method);
      EXPECT_TRUE(served) << method << " " << path;
      EXPECT_TRUE(operation_ids.insert(op["operationId"].get<std::string>()).second)
          << "operationId used twice: " << op["operationId"];
    }
  }
  EXPECT_EQ(operation_ids.size(), api::routes().size());
  std::vector<std::string> refs;
  collect_refs(doc, refs);
  EXPECT_FALSE(refs.empty());
  for (const auto& ref : refs) {
    ASSERT_EQ(ref.rfind("#/", 0), 0u) << ref;
    EXPECT_NO_THROW(static_cast<void>(doc.at(nlohmann::json::json_pointer(ref.substr(1))))) << ref;
  }
}

}  // namespace
}  // namespace clearsky::server
