// No client starves the server (docs/deployment.md "Limits in the server"), against the real
// `clearsky serve`: while 70 slowloris connections, 200 idle keep-alive connections or 70 slow
// readers of a large skydome hold connections, /healthz on a new connection is answered within
// 1 s, during the attack and after it. The limits themselves: idle connections are released when
// workers are scarce, a request head has a deadline, an answer read too slowly is cut, and a
// stopping server does not wait for the heads and idle connections it holds.
#include <gtest/gtest.h>
#include <poll.h>

#include <thread>

#include "tests/server/http/hostile_clients.h"
#include "tests/server/http/serve_process.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

using namespace std::chrono_literals;
using testing::HostileClients;
using testing::ServeProcess;
using Kind = HostileClients::Kind;

// A large answer: a spectral skydome of 512 x 512 pixels (42 MB), streamed in bands of rows.
constexpr const char* kSkydome =
    "/v1/skydome?model=preetham&sun_zenith=30&sun_azimuth=0&size=512&channels=spectral";

// Probes /healthz every 250 ms for `during`, ticking the attack every 500 ms; every probe must
// be answered 200 within 1 s.
void expect_health_answered(int port, HostileClients* attack, std::chrono::milliseconds during) {
  const auto end = std::chrono::steady_clock::now() + during;
  auto next_tick = std::chrono::steady_clock::now();
  int probes = 0;
  while (std::chrono::steady_clock::now() < end) {
    if (attack != nullptr && std::chrono::steady_clock::now() >= next_tick) {
      attack->tick();
      next_tick += 500ms;
    }
    const auto answered = testing::probe(port);
    ++probes;
    ASSERT_TRUE(answered) << "probe " << probes << " not answered";
    EXPECT_LT(answered->count(), 1.0) << "probe " << probes;
    std::this_thread::sleep_for(250ms);
  }
}

// The attack holds its connections for 3 s of probes, then goes; probes go on for 1 s.
void expect_no_starvation(const std::vector<std::string>& options, Kind kind, int connections,
                          const std::string& path = "/healthz") {
  clearsky::testing::TempDir dir;
  ServeProcess server(dir.path, options);
  ASSERT_GT(server.port(), 0) << server.log();
  ASSERT_TRUE(testing::ready(server.port())) << server.log();
  {
    HostileClients attack(kind, server.port(), connections, path);
    ASSERT_EQ(attack.connected(), static_cast<std::size_t>(connections));
    std::this_thread::sleep_for(500ms);
    expect_health_answered(server.port(), &attack, 3s);
  }
  expect_health_answered(server.port(), nullptr, 1s);
}

TEST(Starvation, SlowlorisConnectionsLeaveHealthzAnswered) {
  expect_no_starvation({}, Kind::slowloris, 70);
}

TEST(Starvation, IdleKeepAliveConnectionsLeaveHealthzAnswered) {
  expect_no_starvation({}, Kind::idle_keep_alive, 200);
}

TEST(Starvation, SlowReadersOfALargeSkydomeLeaveHealthzAnswered) {
  expect_no_starvation({}, Kind::slow_reader, 70, kSkydome);
}

TEST(Starvation, IdleConnectionsAreReleasedWhenWorkersAreScarce) {
  // 8 workers for 20 keep-alive connections: each is served, then let go at once.
  expect_no_starvation({"--threads", "8", "--max-queued", "32"}, Kind::idle_keep_alive, 20);
}

TEST(Starvation, TheServerStopsPromptlyWhileHeadsAreIncomplete) {
  clearsky::testing::TempDir dir;
  ServeProcess server(dir.path, {});
  ASSERT_GT(server.port(), 0) << server.log();
  HostileClients slowloris(Kind::slowloris, server.port(), 10);
  HostileClients idle(Kind::idle_keep_alive, server.port(), 10);
  ASSERT_EQ(slowloris.connected() + idle.connected(), 20u);
  std::this_thread::sleep_for(500ms);
  // Not after the head deadline (10 s) or the keep-alive timeout (5 s).
  EXPECT_LT(server.stop().count(), 4.0);
}

// Reads from fd until the server closes the connection (or `limit` passes); returns the bytes
// and whether the close came.
std::pair<std::string, bool> read_until_closed(int fd, std::chrono::seconds limit) {
  std::string data;
  const auto end = std::chrono::steady_clock::now() + limit;
  std::vector<char> buffer(1 << 16);
  while (std::chrono::steady_clock::now() < end) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 100) <= 0) continue;
    const ssize_t n = ::recv(fd, buffer.data(), buffer.size(), 0);
    if (n <= 0) return {data, true};
    data.append(buffer.data(), static_cast<std::size_t>(n));
  }
  return {data, false};
}

TEST(Starvation, ARequestHeadMustArriveWithinItsDeadline) {
  clearsky::testing::TempDir dir;
  ServeProcess server(dir.path, {"--request-head-timeout", "2"});
  ASSERT_GT(server.port(), 0) << server.log();
  // A head sent in two parts within the deadline is answered.
  {
    const int fd = testing::connect_loopback(server.port());
    ASSERT_TRUE(testing::send_all(fd, "GET /healthz HTTP/1.1\r\nHost: clearsky\r\n"));
    std::this_thread::sleep_for(500ms);
    ASSERT_TRUE(testing::send_all(fd, "Connection: close\r\n\r\n"));
    const auto [answer, closed] = read_until_closed(fd, 10s);
    ::close(fd);
    EXPECT_TRUE(closed);
    EXPECT_EQ(answer.rfind("HTTP/1.1 200", 0), 0u) << answer;
  }
  // A head that keeps coming a line every 500 ms is cut after 2 s (400, then closed).
  const int fd = testing::connect_loopback(server.port());
  ASSERT_TRUE(testing::send_all(fd, "GET /healthz HTTP/1.1\r\nHost: clearsky\r\n"));
  const auto start = std::chrono::steady_clock::now();
  bool answered = false;
  for (int line = 0; line < 40 && !answered; ++line) {
    std::this_thread::sleep_for(500ms);
    pollfd p{fd, POLLIN, 0};
    answered = ::poll(&p, 1, 0) > 0;
    if (!answered) testing::send_all(fd, "X-Slow-" + std::to_string(line) + ": 1\r\n");
  }
  const auto [answer, closed] = read_until_closed(fd, 10s);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ::close(fd);
  EXPECT_TRUE(closed);
  EXPECT_TRUE(answer.empty() || answer.rfind("HTTP/1.1 400", 0) == 0) << answer;
  EXPECT_GE(seconds, 1.5);
  EXPECT_LT(seconds, 4.5);
}

// The end of a chunked answer.
bool complete(const std::string& answer) {
  return answer.size() >= 5 && answer.compare(answer.size() - 5, 5, "0\r\n\r\n") == 0;
}

TEST(Starvation, AnAnswerReadBelowTheMinimumSendRateIsCut) {
  clearsky::testing::TempDir dir;
  ServeProcess server(dir.path, {"--min-send-rate", "65536", "--send-rate-grace", "1"});
  ASSERT_GT(server.port(), 0) << server.log();
  ASSERT_TRUE(testing::ready(server.port())) << server.log();
  const std::string request =
      std::string("GET ") + kSkydome + " HTTP/1.1\r\nHost: clearsky\r\nConnection: close\r\n\r\n";
  // Read at once, the skydome arrives whole.
  {
    const int fd = testing::connect_loopback(server.port());
    ASSERT_TRUE(testing::send_all(fd, request));
    const auto [answer, closed] = read_until_closed(fd, 60s);
    ::close(fd);
    EXPECT_TRUE(closed);
    EXPECT_EQ(answer.rfind("HTTP/1.1 200", 0), 0u) << answer.substr(0, 400);
    EXPECT_TRUE(complete(answer)) << answer.size() << " bytes";
  }
  // Not read for 3 s (far below 64 kB/s after the 1 s grace): cut before its end.
  const int fd = testing::connect_loopback(server.port(), 4096);
  ASSERT_TRUE(testing::send_all(fd, request));
  std::this_thread::sleep_for(3s);
  const auto [answer, closed] = read_until_closed(fd, 60s);
  ::close(fd);
  EXPECT_TRUE(closed);
  EXPECT_EQ(answer.rfind("HTTP/1.1 200", 0), 0u) << answer.substr(0, 400);
  EXPECT_FALSE(complete(answer)) << answer.size() << " bytes";
}

}  // namespace
}  // namespace clearsky::server
