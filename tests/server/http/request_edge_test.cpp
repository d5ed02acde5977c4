// The request edge against the real `clearsky serve` process (docs/request-parsing.md "The
// request edge"): hostile input is answered with a 400 naming what is at fault, and afterwards
// the process is alive, answers /healthz within a second and holds no connection open.
// - JSON bodies nested 100,000 deep (600 KB, under the payload limit) used to kill the process
//   (stack overflow);
// - a byte that is not UTF-8 in a parameter, a parameter's name or a body used to leave the
//   request unanswered and its socket in CLOSE-WAIT (the error's JSON could not be written);
// - numbers beyond a double in a body used to be 500s;
// - cpp-httplib's own refusals (URI too long, bad request line or header) named nothing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "tests/server/http/raw_request.h"
#include "tests/server/http/watched_serve_process.h"

namespace clearsky::server {
namespace {

using testing::WatchedServeProcess;

constexpr const char* kToken = "t0ken";
const std::string kSun = "model=oneal&sun_zenith=30&sun_azimuth=0";

std::vector<std::string> server_arguments() {
  return {"--models", "oneal,preetham",      "--prebuild-three", "false",     "--token",
          kToken,     "--payload-max-bytes", "1048576",          "--threads", "8"};
}

// {"a": ... {"a": 1} ...} nested depth deep.
std::string nested_object(int depth) {
  std::string text;
  text.reserve(static_cast<std::size_t>(depth) * 6 + 1);
  for (int i = 0; i < depth; ++i) text += "{\"a\":";
  text += "1";
  text.append(static_cast<std::size_t>(depth), '}');
  return text;
}

// The error of an answer, checked to be the API's format with a parameter.
nlohmann::json error_of(const httplib::Result& r, int status, const std::string& parameter) {
  if (!r) {
    ADD_FAILURE() << "no answer: " << httplib::to_string(r.error());
    return nullptr;
  }
  EXPECT_EQ(r->status, status) << r->body;
  const auto body = nlohmann::json::parse(r->body, nullptr, false);
  EXPECT_TRUE(body.is_object() && body.contains("error")) << r->body;
  if (!body.is_object() || !body.contains("error")) return nullptr;
  EXPECT_EQ(body["error"]["parameter"], parameter) << r->body;
  return body["error"];
}

class RequestEdge : public ::testing::Test {
 protected:
  void SetUp() override {
    server = std::make_unique<WatchedServeProcess>(server_arguments());
    ASSERT_GT(server->port(), 0) << "the server did not start:\n" << server->log();
  }
  void expect_served() {
    EXPECT_TRUE(server->alive()) << "the server ended with signal " << server->end_signal();
    if (server->alive()) {
      EXPECT_TRUE(server->healthy_within_1s());
    }
  }
  std::unique_ptr<WatchedServeProcess> server;
};

TEST_F(RequestEdge, BodiesNestedTooDeepAreRefusedNamingTheMemberAndTheLimit) {
  auto c = server->client();
  c.set_bearer_token_auth(kToken);
  const std::string deep = nested_object(100000);
  for (const char* path : {"/v1/radiance", "/v1/rgb"}) {
    const std::string body =
        R"({"model": "oneal", "sun_zenith": 30, "sun_azimuth": 0, "views": )" + deep + "}";
    const auto error = error_of(c.Post(path, body, "application/json"), 400, "views");
    EXPECT_NE(error.value("message", "").find("64"), std::string::npos) << error;
  }
  // Outside any member: the body; and the write routes' bodies, which have their own parser.
  error_of(c.Post("/v1/radiance", std::string(100000, '[') + std::string(100000, ']'),
                  "application/json"),
           400, "body");
  error_of(c.Post("/v1/jobs", R"({"name": "j", "parameters": )" + deep + "}", "application/json"),
           400, "parameters");
  error_of(
      c.Post("/v1/evaluations", R"({"dataset": "d", "models": )" + deep + "}", "application/json"),
      400, "models");
  expect_served();
  // At the limit the body parses: the answer is about what it says, not its depth.
  const std::string at_limit =
      R"({"model": "oneal", "sun_zenith": 30, "sun_azimuth": 0, "views": )" + nested_object(63) +
      "}";
  const auto error = error_of(c.Post("/v1/rgb", at_limit, "application/json"), 400, "views");
  EXPECT_EQ(error.value("message", "").find("nested"), std::string::npos) << error;
}

TEST_F(RequestEdge, BytesThatAreNotUtf8AreAnsweredAndTheConnectionReleased) {
  const std::string time = "&time=2013-05-27T11:45:00-04:00";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"/v1/radiance?" + kSun + "&view_zenith=45&view_azimuth=0&altitude=%FF", "altitude"},
      {"/v1/radiance?model=oneal&sun_zenith=%FF&sun_azimuth=0&view_zenith=45&view_azimuth=0",
       "sun_zenith"},
      {"/v1/sun?lat=%C3%A9&lon=0" + time, "lat"},
      {"/v1/sun?lat=%EF%BC%95&lon=0" + time, "lat"},
      {"/v1/sun?lat=42&lon=0" + time + "&f%FFoo=1", "f\xEF\xBF\xBDoo"},  // U+FFFD
      {"/v1/rgb?" + kSun + "&view_zenith=45&view_azimuth=%C3%28", "view_azimuth"},
  };
  auto c = server->client();
  for (const auto& [path, parameter] : cases) {
    SCOPED_TRACE(path);
    error_of(c.Get(path), 400, parameter);
  }
  error_of(c.Post("/v1/radiance", "\xFF{}", "application/json"), 400, "body");
  error_of(c.Post("/v1/radiance", "{\"model\": \"\xC3\"}", "application/json"), 400, "model");

  // 300 in a row, each on its own connection: every one answered, none left open. Under
  // `ulimit -n 256` (RequestEdgeFewFiles below) leaked sockets would stop the server.
  const std::size_t files_before = server->open_files();
  for (int i = 0; i < 300; ++i) {
    httplib::Client one("127.0.0.1", server->port());
    one.set_read_timeout(10, 0);
    const auto& [path, parameter] = cases[static_cast<std::size_t>(i) % cases.size()];
    const auto r = one.Get(path);
    ASSERT_TRUE(r) << i << " " << path << ": " << httplib::to_string(r.error());
    ASSERT_EQ(r->status, 400) << r->body;
  }
  // A closed client's socket stays in CLOSE-WAIT until the server's worker sees the close
  // (at once when it is answered); generous for a loaded machine.
  for (int i = 0; i < 200 && server->close_wait_connections() > 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  EXPECT_EQ(server->close_wait_connections(), 0u);
  EXPECT_LE(server->open_files(), files_before + 8);
  expect_served();
}

TEST(RequestEdgeFewFiles, ThreeHundredNonUtf8RequestsLeaveTheServerAnswering) {
  WatchedServeProcess server(server_arguments(), 256);
  ASSERT_GT(server.port(), 0) << "the server did not start:\n" << server.log();
  for (int i = 0; i < 300; ++i) {
    httplib::Client one("127.0.0.1", server.port());
    one.set_read_timeout(10, 0);
    const auto r = one.Get("/v1/sun?lat=%FF&lon=0&time=2013-05-27T11:45:00Z");
    ASSERT_TRUE(r) << i << ": " << httplib::to_string(r.error());
    ASSERT_EQ(r->status, 400) << r->body;
  }
  EXPECT_TRUE(server.alive());
  EXPECT_TRUE(server.healthy_within_1s());
}

TEST_F(RequestEdge, NumbersBeyondADoubleAre400sNamingTheParameter) {
  auto c = server->client();
  const std::string head = R"({"model": "oneal", "sun_zenith": 30, "sun_azimuth": 0, )";
  const std::vector<std::pair<std::string, std::string>> bodies = {
      {head + R"("altitude": 1e999, "views": [[10, 0]]})", "altitude"},
      {head + R"("altitude": -1e999, "views": [[10, 0]]})", "altitude"},
      {head + R"("views": [[1e999, 0]]})", "views"},
      {head + R"("views": [{"view_zenith": 10, "view_azimuth": -1e400}]})", "views"},
      {head + R"("views": [[10, 0]], "altitude": 1)" + std::string(400, '0') + "}", "altitude"},
      {"1e999", "body"},
  };
  for (const char* path : {"/v1/radiance", "/v1/rgb"}) {
    for (const auto& [body, parameter] : bodies) {
      SCOPED_TRACE(std::string(path) + " " + body.substr(0, 120));
      error_of(c.Post(path, body, "application/json"), 400, parameter);
    }
  }
  const std::string view = "&view_zenith=45&view_azimuth=0";
  for (const auto& [query, parameter] : std::vector<std::pair<std::string, std::string>>{
           {"model=oneal&sun_zenith=1e999&sun_azimuth=0" + view, "sun_zenith"},
           {"model=oneal&sun_zenith=30&sun_azimuth=-1e999" + view, "sun_azimuth"},
           {kSun + "&view_zenith=1" + std::string(400, '0') + "&view_azimuth=0", "view_zenith"},
           {kSun + view + "&wavelengths=500,1e999", "wavelengths"},
           {kSun + view + "&altitude=1e999", "altitude"},
       }) {
    SCOPED_TRACE(query);
    error_of(c.Get("/v1/radiance?" + query), 400, parameter);
  }
  expect_served();
}

// Every refusal is the API's JSON with a parameter, cpp-httplib's own included.
TEST_F(RequestEdge, EveryErrorBodyNamesItsParameter) {
  const int port = server->port();
  const auto body_of = [](const std::string& answer) {
    const auto at = answer.find("\r\n\r\n");
    return at == std::string::npos ? std::string() : answer.substr(at + 4);
  };
  const std::vector<std::pair<std::string, std::string>> raw = {
      {"GET /healthz?a=" + std::string(9000, 'a') + " HTTP/1.1\r\nHost: x\r\n\r\n", "uri"},
      {"GARBAGE\r\n\r\n", "request_line"},
      {"GET /healthz HTTP/7.0\r\nHost: x\r\n\r\n", "request_line"},
      {"GET /healthz HTTP/1.1\r\nHost: x\r\nX-Long: " + std::string(9000, 'a') + "\r\n\r\n",
       "headers"},
      {"GET /v1/nowhere HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n", "path"},
      {"PUT /healthz HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n", "method"},
      {"GET /healthz HTTP/1.1\r\nHost: x\r\nContent-Length: 2000000\r\n\r\n", "body"},
      {"POST /v1/radiance HTTP/1.1\r\nHost: x\r\nContent-Length: 1100000\r\n\r\n" +
           std::string(1100000, ' '),
       "body"},
      {"GET /healthz HTTP/1.1\r\nHost: x\r\nRange: bytes=zz\r\n\r\n", "Range"},
      {"POST /v1/radiance HTTP/1.1\r\nHost: x\r\nContent-Length: 5\r\nConnection: close\r\n\r\n"
       "{nope",
       "body"},
  };
  for (const auto& [request, parameter] : raw) {
    SCOPED_TRACE(request.substr(0, 60));
    const std::string answer = testing::ask_before_sending(port, request);
    const auto body = nlohmann::json::parse(body_of(answer), nullptr, false);
    ASSERT_TRUE(body.is_object() && body.contains("error")) << answer.substr(0, 400);
    EXPECT_EQ(body["error"]["parameter"], parameter) << answer.substr(0, 400);
    EXPECT_TRUE(answer.starts_with("HTTP/1.1 4")) << answer.substr(0, 400);
  }
  expect_served();
}

}  // namespace
}  // namespace clearsky::server
