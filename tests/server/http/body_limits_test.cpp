// The two body limits through the real server (server/http/request_body.h, the body policies
// of api/routes/route_table.h): dataset uploads have their own limit (max_upload_bytes) while
// every other route keeps the small payload limit; above either the answer is 413 in the
// project's error format and the client, still sending, reads it (the body is drained, not
// cut), whether the size is declared (Content-Length) or only found on arrival (chunked); a
// client asking first (Expect: 100-continue) is told before it sends the body.
#include <gtest/gtest.h>

#include "tests/server/http/data_server_fixture.h"
#include "tests/server/http/raw_request.h"
#include "tests/support/zero_filled_zip.h"

namespace clearsky::server {
namespace {

constexpr std::size_t kPayload = 64u << 10;
constexpr std::size_t kUpload = 4u << 20;

class BodyLimits : public testing::DataServerFixture {
 protected:
  void SetUp() override { start(std::string("t0ken"), kPayload, kUpload); }
  static void expect_too_large(const httplib::Result& r) {
    ASSERT_TRUE(r) << httplib::to_string(r.error());
    EXPECT_EQ(r->status, 413);
    const auto error = nlohmann::json::parse(r->body)["error"];
    EXPECT_EQ(error["code"], "too_large");
    EXPECT_EQ(error["parameter"], "body");
  }
};

TEST_F(BodyLimits, QueryAndWriteRoutesKeepThePayloadLimit) {
  auto c = client("t0ken");
  // One byte above the limit, then far above it (but under the upload limit).
  expect_too_large(c.Post("/v1/radiance", std::string(kPayload + 1, ' '), "application/json"));
  expect_too_large(c.Post("/v1/rgb", std::string(2u << 20, ' '), "application/json"));
  expect_too_large(c.Post("/v1/jobs", std::string(1u << 20, ' '), "application/json"));
  expect_too_large(c.Post("/v1/evaluations", std::string(kPayload + 10, ' '), "application/json"));
  // At the limit the body is read (and is not a valid request: 400, not 413).
  const auto at_limit = c.Post("/v1/jobs", std::string(kPayload, ' '), "application/json");
  ASSERT_TRUE(at_limit);
  EXPECT_EQ(at_limit->status, 400);
  // The same connection still serves (keep-alive survives a drained 413).
  EXPECT_EQ(c.Get("/v1/datasets")->status, 200);
}

TEST_F(BodyLimits, ChunkedBodiesAreLimitedOnArrival) {
  auto c = client("t0ken");
  const std::string chunk(16u << 10, ' ');
  const auto r = c.Post(
      "/v1/radiance",
      [&](std::size_t, httplib::DataSink& sink) {
        for (int i = 0; i < 16; ++i) sink.write(chunk.data(), chunk.size());  // 256 KiB
        sink.done();
        return true;
      },
      "application/json");
  expect_too_large(r);
}

// Bodies no route reads (a GET's, a POST to an unknown path) are refused before they are read.
TEST_F(BodyLimits, BodiesNoRouteReadsAreRefusedAboveThePayloadLimit) {
  for (const auto& [method, path] : {std::pair<std::string, std::string>{"GET", "/v1/datasets"},
                                     {"POST", "/v1/nowhere"},
                                     {"POST", "/v1/jobs/1/stop"}}) {
    httplib::Client c("127.0.0.1", port);
    httplib::Request req;
    req.method = method;
    req.path = path;
    req.body = std::string(kPayload + 100, 'x');
    req.set_header("Content-Type", "text/plain");
    // Small enough to be sent whole before the answer is read (the server closes unread).
    const auto r = c.send(req);
    ASSERT_TRUE(r) << method << " " << path << ": " << httplib::to_string(r.error());
    expect_too_large(r);
    EXPECT_EQ(r->get_header_value("Connection"), "close");
  }
  // Under the limit an unknown path is the usual 404.
  const auto small = client("t0ken").Post("/v1/nowhere", "{}", "application/json");
  ASSERT_TRUE(small);
  EXPECT_EQ(small->status, 404);
}

TEST_F(BodyLimits, UploadsHaveTheirOwnLimit) {
  auto c = client("t0ken");
  // Above the payload limit, below the upload limit: accepted (it starts as a zip), then
  // imported (it holds no Kider file and ends in junk, so the import fails; nothing stays
  // behind).
  std::string archive = clearsky::testing::zero_filled_zip_bytes(dir.path, {{"a.txt", 16}});
  archive.resize(1u << 20, 'x');
  const auto accepted = c.Post("/v1/datasets?name=big", archive, "application/octet-stream");
  ASSERT_TRUE(accepted);
  ASSERT_EQ(accepted->status, 202) << accepted->body;
  const auto state = finished_import(accepted);
  EXPECT_EQ(state["status"], "failed");
  EXPECT_EQ(state["error"]["code"], "invalid_archive");
  EXPECT_EQ(state["upload_bytes"], 1u << 20);
  // Above the upload limit: 413 whether declared or found on arrival.
  expect_too_large(
      c.Post("/v1/datasets?name=huge", std::string(kUpload + 1, 'x'), "application/octet-stream"));
  EXPECT_EQ(client().Get("/v1/datasets")->body, "[]");
  EXPECT_EQ(body(client().Get("/v1/imports")).size(), 1u);  // the 413s started no import
  EXPECT_TRUE(std::filesystem::is_empty(dir.path / "uploads"));
}

TEST_F(BodyLimits, ExpectContinueIsAnsweredByTheLimitOfTheRoute) {
  const auto head = [](const std::string& target, std::size_t length) {
    return "POST " + target +
           " HTTP/1.1\r\nHost: 127.0.0.1\r\nAuthorization: Bearer t0ken\r\n"
           "Content-Type: application/octet-stream\r\nContent-Length: " +
           std::to_string(length) + "\r\nExpect: 100-continue\r\n\r\n";
  };
  // Above the payload limit on a query route, above the upload limit on the upload route: 413
  // before the body is sent.
  const auto answer = [this, &head](const std::string& target, std::size_t length) {
    return testing::ask_before_sending(port, head(target, length)).substr(0, 12);
  };
  EXPECT_EQ(answer("/v1/radiance", kPayload + 1), "HTTP/1.1 413");
  EXPECT_EQ(answer("/v1/datasets?name=d", kUpload + 1), "HTTP/1.1 413");
  // A complete answer (its length given, so that curl does not wait for the connection to
  // close, sending the body meanwhile), telling the client to close.
  const std::string refused = testing::ask_before_sending(port, head("/v1/radiance", kPayload + 1));
  const auto length_at = refused.find("Content-Length: ");
  ASSERT_NE(length_at, std::string::npos) << refused;
  const std::size_t length = std::stoul(refused.substr(length_at + 16));
  const std::string json = refused.substr(refused.find("\r\n\r\n") + 4);
  EXPECT_EQ(json.size(), length);
  EXPECT_EQ(nlohmann::json::parse(json)["error"]["code"], "too_large");
  EXPECT_NE(refused.find("Connection: close"), std::string::npos) << refused;
  // Within the limits: go on.
  EXPECT_EQ(answer("/v1/radiance", kPayload), "HTTP/1.1 100");
  EXPECT_EQ(answer("/v1/datasets?name=d", kPayload + 1), "HTTP/1.1 100");
}

// A POST with no body at all (no Content-Length, as `curl -X POST URL` sends it) has an empty
// body (RFC 9112 section 6.3): the route answers it (here: 404 for an unknown job, and 400 for a
// radiance request without its JSON), instead of a 400 about an unreadable body.
TEST_F(BodyLimits, APostWithoutABodyHasAnEmptyBody) {
  const auto head = [](const std::string& target) {
    return "POST " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\nAuthorization: Bearer t0ken\r\n\r\n";
  };
  const std::string pause = testing::ask_before_sending(port, head("/v1/jobs/7/pause"));
  EXPECT_EQ(pause.substr(0, 12), "HTTP/1.1 404") << pause;
  const std::string radiance = testing::ask_before_sending(port, head("/v1/radiance"));
  EXPECT_EQ(radiance.substr(0, 12), "HTTP/1.1 400") << radiance;
  EXPECT_EQ(radiance.find("could not be read"), std::string::npos) << radiance;
}

}  // namespace
}  // namespace clearsky::server
