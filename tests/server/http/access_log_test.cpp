// The access log: one JSON object a request, written after the answer is sent, naming the
// client, the request, its answer and the model (docs/deployment.md "Logs").
#include <gtest/gtest.h>
#include <spdlog/sinks/base_sink.h>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "tests/server/http/server_fixture.h"

namespace clearsky::server {
namespace {

// Keeps each message, read under the sink's own lock.
class LineSink final : public spdlog::sinks::base_sink<std::mutex> {
 public:
  std::vector<std::string> lines() {
    std::lock_guard lock(mutex_);
    return lines_;
  }

 protected:
  void sink_it_(const spdlog::details::log_msg& message) override {
    lines_.emplace_back(message.payload.data(), message.payload.size());
  }
  void flush_() override {}

 private:
  std::vector<std::string> lines_;
};

using AccessLogTest = testing::ServerFixture;

TEST_F(AccessLogTest, EachRequestIsOneJsonLineNamingItsAnswer) {
  // The server writes to the logger named "access" (made as the server makes it when no
  // request has been logged yet in this process); no request is in flight while the sink joins.
  auto logger = spdlog::get("access");
  if (!logger) {
    logger = spdlog::stdout_logger_mt("access");
    logger->set_pattern("%v");
  }
  const auto sink = std::make_shared<LineSink>();
  logger->sinks().push_back(sink);

  auto c = client();
  const auto r = c.Get(
      "/v1/radiance?model=testsky&sun_zenith=40&sun_azimuth=100&view_zenith=60&view_azimuth=10");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200);
  // The line is written once the answer has left: wait for it.
  std::vector<std::string> lines;
  for (int i = 0; i < 500 && lines.empty(); ++i) {
    if (i > 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    lines = sink->lines();
  }
  stop();  // no more lines; the sink can leave
  auto& sinks = logger->sinks();
  sinks.erase(std::remove(sinks.begin(), sinks.end(), sink), sinks.end());

  ASSERT_EQ(lines.size(), 1u);
  const nlohmann::json line = nlohmann::json::parse(lines[0]);
  EXPECT_EQ(line["remote"], "127.0.0.1");
  EXPECT_EQ(line["method"], "GET");
  EXPECT_EQ(line["path"], "/v1/radiance");
  EXPECT_EQ(line["status"], 200);
  EXPECT_EQ(line["bytes"], r->body.size());
  EXPECT_EQ(line["model"], "testsky");
  EXPECT_EQ(line["endpoint"], "/v1/radiance");
  ASSERT_TRUE(line["ms"].is_number());
  EXPECT_GE(line["ms"].get<double>(), 0.0);
  // Milliseconds with three decimals.
  const std::string text = lines[0];
  const auto ms = text.find("\"ms\":");
  ASSERT_NE(ms, std::string::npos);
  const auto point = text.find('.', ms);
  const auto end = text.find(',', ms);
  ASSERT_LT(point, end);
  EXPECT_EQ(end - point - 1, 3u) << text;
}

}  // namespace
}  // namespace clearsky::server
