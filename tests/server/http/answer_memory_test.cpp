// The answer memory budget against the real `clearsky serve` (docs/threat-model.md "exhaust
// memory with answers or requests", api/http/answer_memory_budget.h): 60 slow readers of
// spectral skydomes, with a budget of 16 MiB (room for 7 of their bands of 2.4 MB, 60 would hold
// 140 MB): the process's resident peak stays under what it held before plus the budget and a
// margin, /healthz answers within 1 s meanwhile and afterwards, a skydome asked for meanwhile is
// refused with 503 + Retry-After naming answer_memory, and once the readers leave their bands
// come back (GET /metrics) and a skydome is answered again.
#include <gtest/gtest.h>
#include <poll.h>

#include <fstream>
#include <regex>
#include <thread>

#include "tests/server/http/answer_memory_gauge.h"
#include "tests/server/http/hostile_clients.h"
#include "tests/server/http/watched_serve_process.h"
#include "tests/support/sanitizers.h"

namespace clearsky::server {
namespace {

using namespace std::chrono_literals;
using testing::HostileClients;
using testing::WatchedServeProcess;

constexpr std::size_t kBudgetBytes = std::size_t{16} << 20;
// What else the attack may add to the resident memory: 60 worker threads' stacks, the
// computation of the bands being filled, the refusals.
constexpr std::size_t kMarginBytes = std::size_t{32} << 20;

constexpr const char* kSkydome =
    "/v1/skydome?model=preetham&sun_zenith=30&sun_azimuth=0&size=1024&channels=spectral";

// A line of /proc/<pid>/status in bytes (VmRSS, VmHWM).
std::size_t status_bytes(pid_t pid, const std::string& field) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(field + ":", 0) == 0) return std::stoull(line.substr(field.size() + 1)) * 1024;
  }
  return 0;
}

// GET path on a new connection: the answer's head and, unless it is a 200 (a skydome, left
// unread: the connection is closed), its body; empty when nothing came within 30 s.
std::string head_and_error_body(int port, const std::string& path) {
  const int fd = testing::connect_loopback(port);
  if (fd < 0) return {};
  std::string answer;
  if (testing::send_all(
          fd, "GET " + path + " HTTP/1.1\r\nHost: clearsky\r\nConnection: close\r\n\r\n")) {
    const auto end = std::chrono::steady_clock::now() + 30s;
    char buffer[4096];
    while (std::chrono::steady_clock::now() < end) {
      if (answer.rfind("HTTP/1.1 200", 0) == 0 && answer.find("\r\n\r\n") != std::string::npos)
        break;
      pollfd p{fd, POLLIN, 0};
      if (::poll(&p, 1, 100) <= 0) continue;
      const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
      if (n <= 0) break;
      answer.append(buffer, static_cast<std::size_t>(n));
    }
  }
  ::close(fd);
  return answer;
}

// The answer to path, asked again every 100 ms until it starts with status (60 s at most).
std::string await_status(int port, const std::string& path, const std::string& status) {
  const auto end = std::chrono::steady_clock::now() + 60s;
  std::string answer;
  while (std::chrono::steady_clock::now() < end) {
    answer = head_and_error_body(port, path);
    if (answer.rfind("HTTP/1.1 " + status, 0) == 0) return answer;
    std::this_thread::sleep_for(100ms);
  }
  return answer;
}

TEST(AnswerMemory, SlowReadersOfSkydomesStayWithinTheBudget) {
  WatchedServeProcess server({"--models", "preetham", "--prebuild-three", "false",
                              "--answer-memory", std::to_string(kBudgetBytes),
                              // The readers are not cut during the test.
                              "--send-rate-grace", "300", "--write-timeout", "300"});
  ASSERT_GT(server.port(), 0) << server.log();
  ASSERT_TRUE(testing::ready(server.port())) << server.log();
  const std::size_t peak_before = status_bytes(server.pid(), "VmHWM");
  ASSERT_GT(peak_before, 0u);
  {
    HostileClients readers(HostileClients::Kind::slow_reader, server.port(), 60, kSkydome);
    ASSERT_EQ(readers.connected(), 60u);
    // Once the budget is held, the next skydome is refused, naming the limit.
    const std::string refused = await_status(server.port(), kSkydome, "503");
    ASSERT_EQ(refused.rfind("HTTP/1.1 503", 0), 0u) << refused.substr(0, 400);
    EXPECT_NE(refused.find("Retry-After: "), std::string::npos) << refused;
    EXPECT_NE(refused.find(R"("parameter":"answer_memory")"), std::string::npos) << refused;
    EXPECT_NE(refused.find(R"("code":"busy")"), std::string::npos) << refused;
    const double held = testing::reserved_answer_bytes(server);
    EXPECT_GT(held, 0.0);
    EXPECT_LE(held, static_cast<double>(kBudgetBytes));
    for (int i = 0; i < 4; ++i) {
      readers.tick();
      EXPECT_TRUE(server.healthy_within_1s()) << "probe " << i;
      std::this_thread::sleep_for(250ms);
    }
    // Under AddressSanitizer the resident memory says nothing of the budget: freed blocks wait
    // in its quarantine (256 MB by default) and every allocation has shadow memory.
    if (!clearsky::testing::kAddressSanitizer) {
      const std::size_t peak = status_bytes(server.pid(), "VmHWM");
      EXPECT_LT(peak, peak_before + kBudgetBytes + kMarginBytes)
          << "resident peak " << peak << " bytes, " << peak_before << " before the readers";
    }
    EXPECT_TRUE(server.alive()) << server.log();
  }
  // The readers left: their bands come back, and a skydome is answered again.
  EXPECT_TRUE(server.healthy_within_1s());
  const auto end = std::chrono::steady_clock::now() + 60s;
  while (testing::reserved_answer_bytes(server) != 0.0 && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(100ms);
  EXPECT_EQ(testing::reserved_answer_bytes(server), 0.0);
  const std::string answered = await_status(server.port(), kSkydome, "200");
  EXPECT_EQ(answered.rfind("HTTP/1.1 200", 0), 0u) << answered.substr(0, 400);
  EXPECT_TRUE(server.healthy_within_1s());
}

}  // namespace
}  // namespace clearsky::server
