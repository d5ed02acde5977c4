// Radiance and RGB batch answers in the answer memory budget, against the real `clearsky serve`
// (docs/threat-model.md "exhaust memory with answers or requests", api/http/batch_answer_bytes.h):
// with a budget of 4 MiB, a batch whose estimate alone is above it is 413 naming answer_memory;
// while a slow reader of a spectral skydome holds part of the budget, a batch that does not fit
// in the rest is 503 + Retry-After naming answer_memory, and a single view (below the uncounted
// size) is still answered; once the reader leaves, the same batches are answered and the budget
// comes back whole.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "tests/server/http/answer_memory_gauge.h"
#include "tests/server/http/hostile_clients.h"
#include "tests/server/http/watched_serve_process.h"

namespace clearsky::server {
namespace {

using namespace std::chrono_literals;
using testing::HostileClients;
using testing::WatchedServeProcess;

constexpr std::size_t kBudgetBytes = std::size_t{4} << 20;
constexpr const char* kSkydome =
    "/v1/skydome?model=preetham&sun_zenith=30&sun_azimuth=0&size=1024&channels=spectral";
constexpr const char* kSingleView =
    "/v1/radiance?model=preetham&sun_zenith=30&sun_azimuth=0&view_zenith=45&view_azimuth=90";

// The reserved bytes once the answers sent have given theirs back (their responses are
// destroyed just after the client has read the last byte): 0 within 30 s.
double reserved_once_released(const WatchedServeProcess& server) {
  const auto end = std::chrono::steady_clock::now() + 30s;
  while (testing::reserved_answer_bytes(server) != 0.0 && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(50ms);
  return testing::reserved_answer_bytes(server);
}

// A batch of `views` views of the preetham sky (radiance at every wavelength of its grid, or
// RGB) as a JSON body.
std::string batch_body(std::size_t views) {
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t i = 0; i < views; ++i)
    list.push_back({10.0 + static_cast<double>(i % 70), static_cast<double>(i % 360)});
  return nlohmann::json{
      {"model", "preetham"}, {"sun_zenith", 30}, {"sun_azimuth", 0}, {"views", list}}
      .dump();
}

struct Answer {
  int status = 0;
  std::string retry_after;
  std::string parameter;
};

Answer post(const WatchedServeProcess& server, const std::string& path, std::size_t views) {
  auto client = server.client();
  client.set_read_timeout(120, 0);
  const auto r = client.Post(path, batch_body(views), "application/json");
  Answer answer;
  if (!r) return answer;
  answer.status = r->status;
  answer.retry_after = r->get_header_value("Retry-After");
  if (r->status != 200) {
    const auto doc = nlohmann::json::parse(r->body, nullptr, false);
    if (doc.contains("error") && doc["error"]["parameter"].is_string())
      answer.parameter = doc["error"]["parameter"].get<std::string>();
  }
  return answer;
}

TEST(BatchAnswerMemory, BatchesAreCountedInTheAnswerMemoryBudget) {
  WatchedServeProcess server({"--models", "preetham", "--prebuild-three", "false",
                              "--answer-memory", std::to_string(kBudgetBytes), "--send-rate-grace",
                              "300", "--write-timeout", "300"});
  ASSERT_GT(server.port(), 0) << server.log();
  ASSERT_TRUE(testing::ready(server.port())) << server.log();

  // Estimated at about 4.8 kB per view of radiance on preetham's 40 bins, 1.4 kB per RGB view
  // (api/http/batch_answer_bytes.h): 1,000 radiance views are above the budget alone.
  const Answer alone = post(server, "/v1/radiance", 1000);
  EXPECT_EQ(alone.status, 413);
  EXPECT_EQ(alone.parameter, "answer_memory");
  // 700 views of radiance (about 3.4 MB) and 2,500 of RGB (about 3.6 MB) each fit an empty
  // budget, one after the other once the first has given its reservation back.
  EXPECT_EQ(post(server, "/v1/radiance", 700).status, 200);
  EXPECT_EQ(reserved_once_released(server), 0.0);
  EXPECT_EQ(post(server, "/v1/rgb", 2500).status, 200);
  EXPECT_EQ(reserved_once_released(server), 0.0);
  {
    // A slow reader's skydome band (about 2.4 MB) holds the
    // budget: neither batch fits the rest.
    HostileClients reader(HostileClients::Kind::slow_reader, server.port(), 1, kSkydome);
    ASSERT_EQ(reader.connected(), 1u);
    const auto end = std::chrono::steady_clock::now() + 60s;
    while (testing::reserved_answer_bytes(server) <= 0.0 && std::chrono::steady_clock::now() < end)
      std::this_thread::sleep_for(50ms);
    ASSERT_GT(testing::reserved_answer_bytes(server), 0.0) << server.log();
    for (const auto& [path, views] :
         {std::pair<std::string, std::size_t>{"/v1/radiance", 700}, {"/v1/rgb", 2500}}) {
      const Answer busy = post(server, path, views);
      EXPECT_EQ(busy.status, 503) << path;
      EXPECT_EQ(busy.parameter, "answer_memory") << path;
      EXPECT_FALSE(busy.retry_after.empty()) << path;
    }
    // A single view is below the uncounted size: answered whatever the budget holds.
    auto client = server.client();
    const auto single = client.Get(kSingleView);
    ASSERT_TRUE(single);
    EXPECT_EQ(single->status, 200);
    reader.tick();
    EXPECT_TRUE(server.healthy_within_1s());
  }
  // The reader left: its band comes back, the batches are answered, and what they reserved is
  // released once they were sent.
  EXPECT_EQ(reserved_once_released(server), 0.0);
  EXPECT_EQ(post(server, "/v1/radiance", 700).status, 200);
  // The radiance batch's reservation is returned just after its last byte was read: the RGB
  // batch, which fits the budget alone but not beside it, waits for that rather than racing it.
  EXPECT_EQ(reserved_once_released(server), 0.0);
  EXPECT_EQ(post(server, "/v1/rgb", 2500).status, 200);
  EXPECT_EQ(reserved_once_released(server), 0.0);
  EXPECT_TRUE(server.alive()) << server.log();
}

}  // namespace
}  // namespace clearsky::server
