// HTTP semantics through the real server (docs/http-api.md): a known path with another method
// is 405 with Allow; OPTIONS and CORS preflights are answered from the route table for the
// configured origins, and answers (errors included) carry the CORS headers; deterministic
// answers carry Cache-Control and a strong ETag, and If-None-Match gives 304; data answers are
// no-store; creations carry Location; a write without the right token is refused from its
// head, before its body is read.
#include <gtest/gtest.h>

#include "tests/server/http/data_server_fixture.h"
#include "tests/server/http/raw_request.h"

namespace clearsky::server {
namespace {

constexpr const char* kOrigin = "https://sky.example";
constexpr const char* kRadiance =
    "/v1/radiance?model=testsky&sun_zenith=40&sun_azimuth=100&view_zenith=60&view_azimuth=10";

class HttpSemantics : public testing::DataServerFixture {
 protected:
  void SetUp() override { start(std::string("t0ken"), 8u << 20, 64u << 20, {kOrigin}); }
};

TEST_F(HttpSemantics, WrongMethodIs405WithAllow) {
  auto c = client("t0ken");
  const auto put = c.Put("/v1/jobs", "{}", "application/json");
  ASSERT_TRUE(put);
  EXPECT_EQ(put->status, 405);
  EXPECT_EQ(put->get_header_value("Allow"), "GET, HEAD, POST, OPTIONS");
  EXPECT_EQ(body(put)["error"]["code"], "method_not_allowed");
  const auto del = c.Delete("/v1/radiance");
  ASSERT_TRUE(del);
  EXPECT_EQ(del->status, 405);
  EXPECT_EQ(del->get_header_value("Allow"), "GET, HEAD, POST, OPTIONS");
  EXPECT_EQ(c.Get("/v1/jobs/1/pause")->status, 405);
  EXPECT_EQ(c.Get("/v1/nowhere")->status, 404);
  // HEAD is answered where GET is.
  EXPECT_EQ(c.Head("/healthz")->status, 200);
}

TEST_F(HttpSemantics, CorsForConfiguredOrigins) {
  auto c = client();
  const httplib::Headers preflight = {{"Origin", kOrigin},
                                      {"Access-Control-Request-Method", "POST"},
                                      {"Access-Control-Request-Headers", "authorization"}};
  const auto allowed = c.Options("/v1/jobs", preflight);
  ASSERT_TRUE(allowed);
  EXPECT_EQ(allowed->status, 204);
  EXPECT_EQ(allowed->get_header_value("Access-Control-Allow-Origin"), kOrigin);
  EXPECT_EQ(allowed->get_header_value_count("Access-Control-Allow-Origin"), 1u);
  EXPECT_EQ(allowed->get_header_value_count("Vary"), 1u);
  EXPECT_EQ(allowed->get_header_value("Access-Control-Allow-Methods"), "GET, HEAD, POST, OPTIONS");
  EXPECT_EQ(allowed->get_header_value("Access-Control-Allow-Headers"),
            "Authorization, Content-Type");
  EXPECT_EQ(allowed->get_header_value("Access-Control-Max-Age"), "7200");

  const auto other = c.Options("/v1/jobs", {{"Origin", "https://elsewhere.example"},
                                            {"Access-Control-Request-Method", "POST"}});
  ASSERT_TRUE(other);
  EXPECT_EQ(other->status, 204);
  EXPECT_FALSE(other->has_header("Access-Control-Allow-Origin"));
  EXPECT_FALSE(other->has_header("Access-Control-Allow-Methods"));
  EXPECT_EQ(c.Options("/v1/nowhere", preflight)->status, 404);

  // Answers and errors alike carry the origin, so that a page can read either.
  for (const char* path : {"/v1/models", "/v1/datasets/none"}) {
    const auto r = c.Get(path, {{"Origin", kOrigin}});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->get_header_value("Access-Control-Allow-Origin"), kOrigin) << path;
    EXPECT_EQ(r->get_header_value_count("Access-Control-Allow-Origin"), 1u) << path;
    EXPECT_NE(r->get_header_value("Access-Control-Expose-Headers").find("ETag"), std::string::npos);
    EXPECT_EQ(r->get_header_value("Vary"), "Origin");
  }
  EXPECT_FALSE(c.Get("/v1/models", {{"Origin", "https://elsewhere.example"}})
                   ->has_header("Access-Control-Allow-Origin"));
}

TEST_F(HttpSemantics, DeterministicAnswersAreTaggedAndRevalidated) {
  auto c = client();
  const auto first = c.Get(kRadiance);
  ASSERT_TRUE(first);
  ASSERT_EQ(first->status, 200) << first->body;
  EXPECT_EQ(first->get_header_value("Cache-Control"), "public, max-age=86400");
  const std::string tag = first->get_header_value("ETag");
  ASSERT_FALSE(tag.empty());
  const auto again = c.Get(kRadiance, {{"If-None-Match", tag}});
  ASSERT_TRUE(again);
  EXPECT_EQ(again->status, 304);
  EXPECT_TRUE(again->body.empty());
  EXPECT_EQ(again->get_header_value("ETag"), tag);
  const auto other = c.Get(kRadiance, {{"If-None-Match", "\"something else\""}});
  EXPECT_EQ(other->status, 200);
  EXPECT_EQ(other->body, first->body);

  for (const char* path : {"/v1/models", "/openapi.json"}) {
    const auto r = c.Get(path);
    EXPECT_EQ(r->get_header_value("Cache-Control"), "no-cache") << path;
    EXPECT_EQ(c.Get(path, {{"If-None-Match", r->get_header_value("ETag")}})->status, 304) << path;
  }
  // The sun of now, the data and the errors are never stored.
  for (const char* path : {"/v1/sun?lat=42.44&lon=-76.48", "/v1/datasets", "/v1/jobs", "/healthz",
                           "/v1/radiance?model=nope"}) {
    const auto r = c.Get(path);
    EXPECT_EQ(r->get_header_value("Cache-Control"), "no-store") << path;
    EXPECT_FALSE(r->has_header("ETag")) << path;
  }
  EXPECT_EQ(c.Get("/v1/sun?lat=42.44&lon=-76.48&time=2013-05-27T11:45:00-04:00")
                ->get_header_value("Cache-Control"),
            "public, max-age=86400");
}

TEST_F(HttpSemantics, CreationsCarryLocation) {
  {
    storage::Database db = storage::open_database(db_path);
    db.execute("INSERT INTO datasets (name, format, created_utc) VALUES ('d', 'kider2014', 'x')");
  }
  auto c = client("t0ken");
  const auto job = c.Post("/v1/jobs", R"({"name": "n", "schedule": "0 3 * * *", "dataset": "d"})",
                          "application/json");
  ASSERT_EQ(job->status, 201) << job->body;
  const std::string job_location = job->get_header_value("Location");
  EXPECT_EQ(job_location, "/v1/jobs/" + std::to_string(body(job)["id"].get<int>()));
  EXPECT_EQ(c.Get(job_location.c_str())->status, 200);
  const auto run =
      c.Post("/v1/evaluations", R"({"models": ["preetham"], "dataset": "d"})", "application/json");
  ASSERT_EQ(run->status, 202) << run->body;
  EXPECT_EQ(run->get_header_value("Location"), body(run)["location"]);
}

// The head alone: the server answers without waiting for the body (a server that read it
// first would wait, then time out, and answer nothing here).
TEST_F(HttpSemantics, WritesWithoutTheTokenAreRefusedBeforeTheBody) {
  const auto head = [](const std::string& request_line, const std::string& authorization,
                       std::size_t length, bool expect) {
    return request_line + " HTTP/1.1\r\nHost: 127.0.0.1\r\n" + authorization +
           "Content-Type: application/octet-stream\r\nContent-Length: " + std::to_string(length) +
           "\r\n" + (expect ? "Expect: 100-continue\r\n" : "") + "\r\n";
  };
  for (const bool expect : {false, true}) {
    for (const auto& [line, authorization] : std::vector<std::pair<std::string, std::string>>{
             {"POST /v1/datasets?name=d", ""},
             {"POST /v1/datasets?name=d", "Authorization: Bearer wrong\r\n"},
             {"POST /v1/jobs", ""},
             {"DELETE /v1/jobs/1", "Authorization: Basic t0ken\r\n"},
             {"POST /v1/jobs/1/pause", ""}}) {
      const std::size_t length = line.starts_with("POST /v1/datasets") ? 1000000 : 100;
      const std::string answer =
          testing::ask_before_sending(port, head(line, authorization, length, expect));
      EXPECT_EQ(answer.substr(0, 12), "HTTP/1.1 401") << line << " " << expect << "\n" << answer;
      EXPECT_NE(answer.find("WWW-Authenticate: Bearer"), std::string::npos) << answer;
      EXPECT_NE(answer.find("Connection: close"), std::string::npos) << answer;
    }
  }
  EXPECT_TRUE(!std::filesystem::exists(dir.path / "uploads") ||
              std::filesystem::is_empty(dir.path / "uploads"));
  EXPECT_EQ(client().Get("/v1/imports")->body, "[]");
}

// A refused request's body is never read as further requests: here it is made of requests,
// which a server that kept reading the connection would answer.
TEST_F(HttpSemantics, ARefusedBodyIsNotReadAsTheNextRequest) {
  std::string smuggled;
  while (smuggled.size() < 4000) smuggled += "GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n";
  for (const std::string& line :
       {std::string("POST /v1/jobs"), std::string("DELETE /v1/jobs/1"),
        std::string("POST /v1/nowhere"), std::string("PUT /v1/jobs"), std::string("GET /healthz"),
        std::string("POST /v1/datasets?colour=red")}) {
    const std::string authorization =
        line.find("datasets") != std::string::npos ? "Authorization: Bearer t0ken\r\n" : "";
    const std::string answer = testing::exchange_until_close(
        port, line + " HTTP/1.1\r\nHost: 127.0.0.1\r\n" + authorization +
                  "Content-Type: text/plain\r\nContent-Length: " + std::to_string(smuggled.size()) +
                  "\r\n\r\n" + smuggled);
    std::size_t answers = 0;
    for (std::size_t at = answer.find("HTTP/1.1 "); at != std::string::npos;
         at = answer.find("HTTP/1.1 ", at + 1))
      ++answers;
    EXPECT_EQ(answers, 1u) << line << "\n" << answer.substr(0, 400);
  }
}

}  // namespace
}  // namespace clearsky::server
