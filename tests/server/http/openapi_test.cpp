// /openapi.json parses, is OpenAPI 3, describes every served route, and every $ref resolves.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

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

TEST_F(OpenApiTest, DescribesEveryRoute) {
  auto c = client();
  const auto r = c.Get("/openapi.json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200);
  const auto doc = nlohmann::json::parse(r->body);
  EXPECT_EQ(doc["openapi"].get<std::string>().substr(0, 2), "3.");
  ASSERT_TRUE(doc["info"].contains("title"));
  for (const auto& [method, path] : HttpServer::routes()) {
    std::string lower = method;
    for (char& ch : lower) ch = static_cast<char>(std::tolower(ch));
    ASSERT_TRUE(doc["paths"].contains(path)) << path;
    ASSERT_TRUE(doc["paths"][path].contains(lower)) << method << " " << path;
    const auto& op = doc["paths"][path][lower];
    EXPECT_TRUE(op.contains("summary")) << path;
    EXPECT_TRUE(op["responses"].contains("200") || op["responses"].contains("201") ||
                op["responses"].contains("202"))
        << path;
    // Every served route answers (no route is described but missing).
    if (method == "GET" && path.rfind("/v1/", 0) != 0) {
      const auto served = c.Get(path);
      ASSERT_TRUE(served);
      EXPECT_NE(served->status, 404) << path;
    }
  }
  // Nothing is described that is not served.
  for (const auto& [path, operations] : doc["paths"].items()) {
    for (const auto& [method, op] : operations.items()) {
      bool served = false;
      for (const auto& [m, p] : HttpServer::routes()) {
        std::string lower = m;
        for (char& ch : lower) ch = static_cast<char>(std::tolower(ch));
        served = served || (p == path && lower == method);
      }
      EXPECT_TRUE(served) << method << " " << path;
    }
  }
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
