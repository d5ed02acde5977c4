// poll(2)-based reads and writes of one connection with its deadlines.
#include "server/http/connection_stream.h"

#include <linux/sockios.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <string_view>
#include <utility>

namespace clearsky::server {

namespace {

using Clock = ConnectionStream::Clock;
using std::chrono::milliseconds;

// Longest single poll: scarcity, the send rate and the server's stop are re-checked this often
// while a connection waits.
constexpr milliseconds kSlice{50};
constexpr std::size_t kBufferBytes = 4096;

void ip_and_port(const sockaddr_storage& address, socklen_t length, std::string& ip, int& port) {
  if (address.ss_family == AF_INET)
    port = ntohs(reinterpret_cast<const sockaddr_in&>(address).sin_port);
  else if (address.ss_family == AF_INET6)
    port = ntohs(reinterpret_cast<const sockaddr_in6&>(address).sin6_port);
  else
    return;
  std::array<char, NI_MAXHOST> host{};
  if (::getnameinfo(reinterpret_cast<const sockaddr*>(&address), length, host.data(), host.size(),
                    nullptr, 0, NI_NUMERICHOST) == 0)
    ip = host.data();
}

}  // namespace

ConnectionStream::ConnectionStream(socket_t sock, const ConnectionLimits& limits,
                                   const WorkerLoad& load, std::function<bool()> stopping)
    : sock_(sock),
      limits_(limits),
      load_(load),
      stopping_(std::move(stopping)),
      buffer_(kBufferBytes) {}

ConnectionStream::Wait ConnectionStream::wait(
    short events, Clock::time_point deadline,
    const std::function<bool(Clock::time_point)>& give_up) const {
  while (true) {
    Clock::time_point now = Clock::now();
    if (now >= deadline) return Wait::timeout;
    const auto slice =
        std::clamp(std::chrono::ceil<milliseconds>(deadline - now), milliseconds{1}, kSlice);
    pollfd p{sock_, events, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(slice.count()));
    if (ready > 0) return (p.revents & POLLNVAL) != 0 ? Wait::failed : Wait::ready;
    if (ready < 0 && errno != EINTR) return Wait::failed;
    if (give_up && give_up(Clock::now())) return Wait::timeout;
  }
}

bool ConnectionStream::wait_for_request(bool first) {
  if (buffer_begin_ < buffer_end_) return true;
  const auto start = Clock::now();
  // A new connection's first request is usually there already; a client slow to send it (a
  // loaded machine) gets the grace of a head before scarcity closes it. Between requests, an
  // idle connection goes at once.
  const auto give_up = [&](Clock::time_point now) {
    return stopping_() || (load_.scarce() && (!first || now - start >= limits_.scarce_head_grace));
  };
  return wait(POLLIN, start + limits_.keep_alive_timeout, give_up) == Wait::ready;
}

void ConnectionStream::begin_request() {
  in_head_ = true;
  head_complete_ = false;
  head_start_ = Clock::now();
  answering_ = false;
  held_head_.clear();
}

void ConnectionStream::end_head() {
  in_head_ = false;
  head_complete_ = true;
}

ssize_t ConnectionStream::read(char* ptr, std::size_t size) {
  if (buffer_begin_ < buffer_end_) {
    const std::size_t n = std::min(size, buffer_end_ - buffer_begin_);
    std::memcpy(ptr, buffer_.data() + buffer_begin_, n);
    buffer_begin_ += n;
    return static_cast<ssize_t>(n);
  }
  auto deadline = Clock::now() + limits_.read_timeout;
  if (in_head_) deadline = std::min(deadline, head_start_ + limits_.head_timeout);
  const auto head_too_slow = [this](Clock::time_point now) {
    return in_head_ &&
           (stopping_() || (load_.scarce() && now - head_start_ >= limits_.scarce_head_grace));
  };
  // Large reads (bodies) go straight to the caller; small ones (the head, read a byte at a
  // time by cpp-httplib) through the buffer.
  const bool direct = size >= buffer_.size();
  while (true) {
    const ssize_t n =
        ::recv(sock_, direct ? ptr : buffer_.data(), direct ? size : buffer_.size(), MSG_DONTWAIT);
    if (n >= 0) {
      if (direct || n == 0) return n;
      buffer_begin_ = 0;
      buffer_end_ = static_cast<std::size_t>(n);
      return read(ptr, size);
    }
    if (errno == EINTR) continue;
    if (errno != EAGAIN && errno != EWOULDBLOCK) return -1;
    if (wait(POLLIN, deadline, head_too_slow) != Wait::ready) return -1;
  }
}

Clock::time_point ConnectionStream::send_rate_deadline() const {
  int unsent = 0;  // bytes in the send queue, not yet acknowledged by the client
  if (::ioctl(sock_, SIOCOUTQ, &unsent) != 0) unsent = 0;
  const std::size_t delivered = answer_bytes_ - std::min<std::size_t>(answer_bytes_, unsent);
  const double seconds =
      static_cast<double>(delivered) / static_cast<double>(limits_.min_send_rate_bytes_per_s);
  return answer_start_ + limits_.send_rate_grace +
         std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

ssize_t ConnectionStream::write(const char* ptr, std::size_t size) {
  // A head is far below this; a larger first write is not held.
  constexpr std::size_t kHeldHeadMaxBytes = 16 * 1024;
  if (!answering_) {
    in_head_ = false;
    answer_start_ = Clock::now();
    answer_bytes_ = 0;
    // An interim answer (100 Continue) goes at once: the client waits for it to send the body.
    constexpr std::string_view kInterim = "HTTP/1.1 1";
    if (std::string_view(ptr, size).substr(0, kInterim.size()) == kInterim) {
      const iovec part{const_cast<char*>(ptr), size};
      return send_parts(&part, 1);
    }
    answering_ = true;
    if (size <= kHeldHeadMaxBytes) {
      held_head_.assign(ptr, size);
      return static_cast<ssize_t>(size);
    }
  }
  while (!held_head_.empty()) {
    const iovec parts[2] = {{held_head_.data(), held_head_.size()}, {const_cast<char*>(ptr), size}};
    const ssize_t n = send_parts(parts, 2);
    if (n < 0) return -1;
    const auto sent = static_cast<std::size_t>(n);
    if (sent < held_head_.size()) {
      held_head_.erase(0, sent);
      continue;
    }
    const std::size_t of_body = sent - held_head_.size();
    held_head_.clear();
    if (of_body > 0) return static_cast<ssize_t>(of_body);
  }
  const iovec part{const_cast<char*>(ptr), size};
  return send_parts(&part, 1);
}

bool ConnectionStream::flush_answer() {
  while (!held_head_.empty()) {
    const iovec part{held_head_.data(), held_head_.size()};
    const ssize_t n = send_parts(&part, 1);
    if (n < 0) {
      held_head_.clear();
      return false;
    }
    held_head_.erase(0, static_cast<std::size_t>(n));
  }
  return true;
}

ssize_t ConnectionStream::send_parts(const iovec* parts, std::size_t count) {
  const auto deadline = Clock::now() + limits_.write_timeout;
  const auto too_slow = [this](Clock::time_point now) {
    return limits_.min_send_rate_bytes_per_s > 0 && now > send_rate_deadline();
  };
  msghdr message{};
  message.msg_iov = const_cast<iovec*>(parts);
  message.msg_iovlen = count;
  while (true) {
    const ssize_t n = ::sendmsg(sock_, &message, MSG_DONTWAIT | MSG_NOSIGNAL);
    if (n >= 0) {
      answer_bytes_ += static_cast<std::size_t>(n);
      return n;
    }
    if (errno == EINTR) continue;
    if (errno != EAGAIN && errno != EWOULDBLOCK) return -1;
    if (too_slow(Clock::now()) || wait(POLLOUT, deadline, too_slow) != Wait::ready) return -1;
  }
}

bool ConnectionStream::is_readable() const {
  if (buffer_begin_ < buffer_end_) return true;
  return wait(POLLIN, Clock::now() + limits_.read_timeout, nullptr) == Wait::ready;
}

bool ConnectionStream::is_writable() const {
  // Whether the client is still there; a write waits for room itself.
  pollfd p{sock_, POLLIN | POLLOUT, 0};
  if (::poll(&p, 1, 0) < 0) return false;
  if ((p.revents & (POLLERR | POLLHUP | POLLNVAL)) != 0) return false;
  if ((p.revents & POLLIN) != 0) {
    char byte = 0;
    return ::recv(sock_, &byte, 1, MSG_PEEK | MSG_DONTWAIT) > 0;
  }
  return true;
}

void ConnectionStream::known_address(Address& address, AskAddress ask, std::string& ip,
                                     int& port) const {
  if (!address.known) {
    sockaddr_storage storage{};
    socklen_t length = sizeof storage;
    if (ask(sock_, reinterpret_cast<sockaddr*>(&storage), &length) == 0)
      ip_and_port(storage, length, address.ip, address.port);
    address.known = true;
  }
  ip = address.ip;
  port = address.port;
}

void ConnectionStream::get_remote_ip_and_port(std::string& ip, int& port) const {
  known_address(remote_, ::getpeername, ip, port);
}

void ConnectionStream::get_local_ip_and_port(std::string& ip, int& port) const {
  known_address(local_, ::getsockname, ip, port);
}

socket_t ConnectionStream::socket() const { return sock_; }

}  // namespace clearsky::server
