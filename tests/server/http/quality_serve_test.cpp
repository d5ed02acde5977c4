// Quality levels through the real `clearsky serve` (docs/quality-levels.md): a draft request
// answers and states its quality, a standard answer equals the answer without quality, and a
// fresh server with an empty table cache answers Bruneton from its draft tables before its
// standard tables are ready (then a reference request waits within --build-wait-ms: 503 naming
// the level). Timeouts are generous: the machine may be loaded; nothing asserts a duration.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <thread>

#include "tests/server/http/hostile_clients.h"
#include "tests/server/http/watched_serve_process.h"

namespace clearsky::server {
namespace {

using testing::WatchedServeProcess;

const std::string kView = "&sun_zenith=40&sun_azimuth=180&view_zenith=50&view_azimuth=100";

nlohmann::json readiness(httplib::Client& c) {
  const auto r = c.Get("/readyz");
  return r ? nlohmann::json::parse(r->body, nullptr, false) : nlohmann::json();
}

std::string level_status(const nlohmann::json& ready, const char* model, const char* level) {
  if (!ready.is_object() || !ready.contains("models") || !ready["models"].contains(model))
    return "";
  return ready["models"][model]["levels"][level]["status"].get<std::string>();
}

TEST(QualityServe, DraftAnswersAndStandardIsTheAnswerWithoutQuality) {
  // The requests' three wavelengths are configurations of their own, built on first use: a
  // long build wait lets a loaded machine build them (O'Neal's draft is 64 ray samples) instead
  // of answering 503.
  WatchedServeProcess server(
      {"--models", "oneal", "--prebuild-three", "false", "--build-wait-ms", "120000"});
  ASSERT_GT(server.port(), 0) << server.log();
  // The start builds (the draft, then the standard) are awaited, not raced, so that no standard
  // answer below comes from the draft.
  ASSERT_TRUE(testing::ready(server.port(), std::chrono::seconds(300))) << server.log();
  auto c = server.client(120);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
  while ((level_status(readiness(c), "oneal", "draft") != "ready" ||
          level_status(readiness(c), "oneal", "standard") != "ready") &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const std::string base = "/v1/radiance?model=oneal" + kView + "&wavelengths=450,550,650";
  const auto draft = c.Get(base + "&quality=draft");
  ASSERT_TRUE(draft);
  ASSERT_EQ(draft->status, 200) << draft->body;
  const auto d = nlohmann::json::parse(draft->body);
  EXPECT_EQ(d["quality"], "draft");
  EXPECT_EQ(d["served_quality"], "draft");
  EXPECT_EQ(d["quality_setting"]["samples"], 64.0);
  EXPECT_TRUE(d["quality_error"]["p95_relative"].is_number());
  EXPECT_EQ(draft->get_header_value("Clearsky-Quality"), "draft");
  EXPECT_EQ(draft->get_header_value("Clearsky-Served-Quality"), "draft");

  const auto plain = c.Get(base);
  const auto standard = c.Get(base + "&quality=standard");
  ASSERT_TRUE(plain && standard);
  ASSERT_EQ(plain->status, 200) << plain->body;
  ASSERT_EQ(standard->status, 200) << standard->body;
  // The same answer, byte for byte (both state quality standard), hence the same ETag.
  EXPECT_EQ(plain->body, standard->body);
  EXPECT_EQ(plain->get_header_value("ETag"), standard->get_header_value("ETag"));
  EXPECT_NE(nlohmann::json::parse(plain->body)["samples"], d["samples"]);

  const auto refused = c.Get(base + "&quality=fast");
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 400);
  EXPECT_EQ(nlohmann::json::parse(refused->body)["error"]["parameter"], "quality");
}

TEST(QualityServe, AFreshServerAnswersBrunetonFromItsDraftBeforeStandardIsReady) {
  const auto start = std::chrono::steady_clock::now();
  WatchedServeProcess server({"--models", "bruneton", "--prebuild-three", "false", "--prebuild",
                              "bruneton:draft,bruneton:standard", "--build-wait-ms", "200",
                              "--builder-threads", "1", "--retry-after", "1"});
  ASSERT_GT(server.port(), 0) << server.log();
  auto c = server.client(120);
  nlohmann::json ready;
  const auto deadline = start + std::chrono::seconds(600);
  while (std::chrono::steady_clock::now() < deadline && server.alive()) {
    ready = readiness(c);
    if (level_status(ready, "bruneton", "draft") == "ready") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_EQ(level_status(ready, "bruneton", "draft"), "ready") << ready.dump() << server.log();
  const double draft_ready_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("bruneton_draft_ready_s", std::to_string(draft_ready_s));
  std::printf("bruneton draft ready %.1f s after the start\n", draft_ready_s);
  // The standard tables take many times longer than the draft (docs/quality-levels.md).
  if (level_status(ready, "bruneton", "standard") == "ready")
    GTEST_SKIP() << "the standard tables were ready as soon as the draft";
  const auto not_ready = c.Get("/readyz");
  ASSERT_TRUE(not_ready);
  EXPECT_EQ(not_ready->status, 503) << not_ready->body;

  const std::string query = "/v1/radiance?model=bruneton" + kView;
  for (const std::string& asked : {query + "&quality=standard", query}) {
    const auto r = c.Get(asked);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    const auto j = nlohmann::json::parse(r->body);
    if (j["served_quality"] == "standard") GTEST_SKIP() << "the standard tables became ready";
    EXPECT_EQ(j["quality"], "standard");
    EXPECT_EQ(j["served_quality"], "draft");
    EXPECT_EQ(j["quality_setting"]["table_mu_size"], 32.0);
    EXPECT_EQ(r->get_header_value("Clearsky-Served-Quality"), "draft");
    EXPECT_EQ(r->get_header_value("Cache-Control"), "no-store");
  }
  const auto draft = c.Get(query + "&quality=draft");
  ASSERT_TRUE(draft);
  ASSERT_EQ(draft->status, 200) << draft->body;
  EXPECT_EQ(nlohmann::json::parse(draft->body)["served_quality"], "draft");

  // Reference is never answered from another level: it waits like any build, then 503.
  const auto reference = c.Get(query + "&quality=reference&wavelengths=550");
  ASSERT_TRUE(reference);
  EXPECT_EQ(reference->status, 503) << reference->body;
  EXPECT_FALSE(reference->get_header_value("Retry-After").empty());
  const auto error = nlohmann::json::parse(reference->body)["error"];
  EXPECT_EQ(error["parameter"], "model");
  EXPECT_NE(error["message"].get<std::string>().find("quality reference"), std::string::npos)
      << error.dump();
}

}  // namespace
}  // namespace clearsky::server
