// Clients that hold a server's connections without finishing their business, written on raw
// loopback sockets (docs/deployment.md "Measuring starvation"), and the probe that checks the
// server still answers meanwhile: slowloris (a request head sent a line at a time), idle
// keep-alive connections (one request answered, then silence) and slow readers (a large answer
// asked for and hardly read). The attackers are plain data; tick() advances the slowloris heads
// and the slow reads. Not thread-safe.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace clearsky::server::testing {

// A connected loopback socket with send/receive timeouts (-1 when it cannot connect).
inline int connect_loopback(int port, int receive_buffer_bytes = 0) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (receive_buffer_bytes > 0)
    ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &receive_buffer_bytes, sizeof receive_buffer_bytes);
  timeval timeout{5, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &timeout, sizeof timeout);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

inline bool send_all(int fd, const std::string& data) {
  std::size_t sent = 0;
  while (sent < data.size()) {
    const ssize_t n = ::send(fd, data.data() + sent, data.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) return false;
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

// How long GET path took to be answered 200 on a new connection; nullopt when it was not
// (refused, closed, another status, or nothing within 5 s).
inline std::optional<std::chrono::duration<double>> probe(int port,
                                                          const std::string& path = "/healthz") {
  const auto start = std::chrono::steady_clock::now();
  const int fd = connect_loopback(port);
  if (fd < 0) return std::nullopt;
  std::string answer;
  if (send_all(fd, "GET " + path + " HTTP/1.1\r\nHost: clearsky\r\nConnection: close\r\n\r\n")) {
    char buffer[1024];
    while (answer.find("\r\n") == std::string::npos) {
      const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
      if (n <= 0) break;
      answer.append(buffer, static_cast<std::size_t>(n));
    }
  }
  ::close(fd);
  if (answer.rfind("HTTP/1.1 200", 0) != 0) return std::nullopt;
  return std::chrono::steady_clock::now() - start;
}

// Whether GET /readyz is answered 200 within `within` (the model tables are built): a sky
// request asked before may be a 503.
inline bool ready(int port, std::chrono::seconds within = std::chrono::seconds(60)) {
  const auto end = std::chrono::steady_clock::now() + within;
  while (std::chrono::steady_clock::now() < end) {
    if (probe(port, "/readyz")) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

// Connections of one kind of attacker; their sockets close with the object.
class HostileClients {
 public:
  enum class Kind { slowloris, idle_keep_alive, slow_reader };

  // count connections to port; slow readers ask for path (a large answer).
  HostileClients(Kind kind, int port, int count, const std::string& path = "/healthz")
      : kind_(kind) {
    for (int i = 0; i < count; ++i) {
      const int fd = connect_loopback(port, kind == Kind::slow_reader ? 4096 : 0);
      if (fd < 0) continue;
      bool ok = false;
      if (kind == Kind::slowloris) {
        ok = send_all(fd, "GET /healthz HTTP/1.1\r\nHost: clearsky\r\n");
      } else if (kind == Kind::idle_keep_alive) {
        // Not waiting for the answer: all connections are open at once (tick() reads them).
        ok = send_all(fd, "GET /healthz HTTP/1.1\r\nHost: clearsky\r\n\r\n");
      } else {
        ok = send_all(fd, "GET " + path + " HTTP/1.1\r\nHost: clearsky\r\n\r\n");
      }
      if (ok)
        fds_.push_back(fd);
      else
        ::close(fd);
    }
  }
  ~HostileClients() {
    for (int fd : fds_) ::close(fd);
  }
  HostileClients(const HostileClients&) = delete;
  HostileClients& operator=(const HostileClients&) = delete;

  std::size_t connected() const { return fds_.size(); }

  // One more header line per slowloris head, a few bytes read per slow reader, the answers
  // read on the idle connections.
  void tick() {
    ++ticks_;
    for (int fd : fds_) {
      if (kind_ == Kind::slowloris) {
        send_all(fd, "X-Slow-" + std::to_string(ticks_) + ": 1\r\n");
      } else if (kind_ == Kind::slow_reader) {
        char buffer[4];
        ::recv(fd, buffer, sizeof buffer, MSG_DONTWAIT);
      } else {
        char buffer[1024];
        while (::recv(fd, buffer, sizeof buffer, MSG_DONTWAIT) > 0) {
        }
      }
    }
  }

 private:
  Kind kind_;
  std::vector<int> fds_;
  int ticks_ = 0;
};

}  // namespace clearsky::server::testing
