// The graceful drain of a real `clearsky serve` (docs/deploy.md "Graceful drain"): after
// SIGTERM /readyz answers 503 (code draining) for --drain-delay, the listening socket closes,
// a streamed skydome in flight (its reader paused through the whole drain) still arrives
// complete, and the process exits 0; a reader that never reads is cut at --drain-timeout and
// the process still exits 0. No timing is asserted beyond generous deadlines.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "tests/server/http/watched_serve_process.h"

namespace clearsky::server {
namespace {

using Clock = std::chrono::steady_clock;
using testing::WatchedServeProcess;

// A connected loopback socket (-1 when the connection is refused).
int connect_to(int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    ::close(fd);
    return -1;
  }
  timeval timeout{60, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  return fd;
}

// Reads up to at least `bytes` more bytes into out; false when the connection ended first.
bool read_at_least(int fd, std::string& out, std::size_t bytes) {
  const std::size_t target = out.size() + bytes;
  char buffer[65536];
  while (out.size() < target) {
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0) return false;
    out.append(buffer, static_cast<std::size_t>(n));
  }
  return true;
}

void read_to_end(int fd, std::string& out) {
  char buffer[65536];
  for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;)
    out.append(buffer, static_cast<std::size_t>(n));
}

// The body of a chunked answer when it ended with its last chunk (RFC 9112 section 7.1);
// nullopt when it was cut short.
std::optional<std::string> dechunked(const std::string& answer) {
  std::size_t at = answer.find("\r\n\r\n");
  if (at == std::string::npos) return std::nullopt;
  at += 4;
  std::string body;
  while (true) {
    const std::size_t line_end = answer.find("\r\n", at);
    if (line_end == std::string::npos) return std::nullopt;
    const std::size_t size = std::stoul(answer.substr(at, line_end - at), nullptr, 16);
    at = line_end + 2;
    if (size == 0) return body;
    if (answer.size() < at + size + 2) return std::nullopt;
    body.append(answer, at, size);
    at += size + 2;
  }
}

bool wait_until(const std::function<bool()>& condition, std::chrono::seconds limit) {
  const auto deadline = Clock::now() + limit;
  while (!condition()) {
    if (Clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return true;
}

bool ready(const WatchedServeProcess& server) {
  const auto r = server.client(5).Get("/readyz");
  return r && r->status == 200;
}

// A spectral skydome of about 75 MB: far more than the socket buffers hold, so its stream is
// still in flight while its reader pauses.
const std::string kSkydome =
    "GET /v1/skydome?model=preetham&sun_zenith=40&sun_azimuth=90&size=768&channels=spectral "
    "HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n";

TEST(GracefulDrain, AStreamedSkydomeInFlightCompletesAndReadyzSays503) {
  WatchedServeProcess server({"--models", "preetham", "--prebuild-three", "false",
                              "--min-send-rate", "0", "--drain-delay", "5", "--drain-timeout",
                              "120"});
  ASSERT_GT(server.port(), 0) << server.log();
  ASSERT_TRUE(wait_until([&] { return ready(server); }, std::chrono::seconds(120)));

  const int stream = connect_to(server.port());
  ASSERT_GE(stream, 0);
  ASSERT_EQ(::send(stream, kSkydome.data(), kSkydome.size(), 0),
            static_cast<ssize_t>(kSkydome.size()));
  std::string answer;
  ASSERT_TRUE(read_at_least(stream, answer, 256 * 1024)) << answer.substr(0, 300);
  ASSERT_NE(answer.find("HTTP/1.1 200"), std::string::npos) << answer.substr(0, 300);

  // The reader pauses from here until the listening socket has closed.
  server.signal(SIGTERM);
  bool saw_draining = false;
  ASSERT_TRUE(wait_until(
      [&] {
        const auto r = server.client(5).Get("/readyz");
        if (r && r->status == 503 && nlohmann::json::parse(r->body)["error"]["code"] == "draining")
          saw_draining = true;
        return saw_draining;
      },
      std::chrono::seconds(60)))
      << server.log();
  // /healthz (liveness) stays 200 while the server drains.
  const auto health = server.client(5).Get("/healthz");
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
  // After --drain-delay the listening socket closes: new connections are refused.
  ASSERT_TRUE(wait_until(
      [&] {
        const int probe = connect_to(server.port());
        if (probe >= 0) ::close(probe);
        return probe < 0;
      },
      std::chrono::seconds(60)))
      << server.log();
  EXPECT_TRUE(server.alive()) << "the server ended with a skydome in flight\n" << server.log();

  read_to_end(stream, answer);
  ::close(stream);
  const std::optional<std::string> image = dechunked(answer);
  ASSERT_TRUE(image.has_value()) << "the skydome was cut after " << answer.size() << " bytes";
  EXPECT_GT(image->size(), std::size_t{768} * 768 * 4 * 31);
  EXPECT_EQ(image->substr(0, 4), std::string("\x76\x2f\x31\x01", 4));  // the OpenEXR magic

  ASSERT_TRUE(wait_until([&] { return !server.alive(); }, std::chrono::seconds(120)))
      << server.log();
  EXPECT_EQ(server.end_signal(), 0);
  EXPECT_EQ(server.exit_status(), 0) << server.log();
}

TEST(GracefulDrain, ConnectionsLeftAtTheDrainTimeoutAreCutAndTheProcessExitsZero) {
  WatchedServeProcess server({"--models", "preetham", "--prebuild-three", "false",
                              "--min-send-rate", "0", "--write-timeout", "3000", "--drain-delay",
                              "0", "--drain-timeout", "2"});
  ASSERT_GT(server.port(), 0) << server.log();
  ASSERT_TRUE(wait_until([&] { return ready(server); }, std::chrono::seconds(120)));
  // A client that asks for a skydome and never reads it.
  const int stuck = connect_to(server.port());
  ASSERT_GE(stuck, 0);
  ASSERT_EQ(::send(stuck, kSkydome.data(), kSkydome.size(), 0),
            static_cast<ssize_t>(kSkydome.size()));
  std::string answer;
  ASSERT_TRUE(read_at_least(stuck, answer, 1)) << server.log();

  server.signal(SIGTERM);
  // Far sooner than the write timeout (3000 s) would end it.
  ASSERT_TRUE(wait_until([&] { return !server.alive(); }, std::chrono::seconds(120)))
      << server.log();
  ::close(stuck);
  EXPECT_EQ(server.end_signal(), 0);
  EXPECT_EQ(server.exit_status(), 0) << server.log();
  EXPECT_NE(server.log().find("were cut"), std::string::npos) << server.log();
}

}  // namespace
}  // namespace clearsky::server
