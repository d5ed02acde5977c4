// One client connection as cpp-httplib's Stream, with the time limits of docs/deployment.md
// "Limits in the server", enforced with poll(2) around non-blocking reads and writes:
// - waiting for a request: up to the keep-alive timeout, cut at once while workers are scarce;
// - a request head (request line and headers) must arrive whole within head_timeout from its
//   first byte (slowloris), and within a short grace while workers are scarce;
// - a read (body) or a blocked write waits at most read_timeout / write_timeout;
// - an answer must reach the client at min_send_rate bytes/s on average once send_rate_grace
//   has passed since its first byte (slow readers). Reached means read by the client, not
//   queued in the kernel: the bytes still in the socket's send queue (SIOCOUTQ) do not count.
// The head of an answer (cpp-httplib writes it in one call) is held back and leaves with the
// first write of the body in one sendmsg(2): an answer whose body is one write leaves in one
// system call, so a process killed between the two never leaves a proxy holding a head without
// its body (a request HAProxy cannot send again: docs/deploy.md "Scale-out on one host"), and a
// small answer takes one TCP segment instead of two. flush_answer() sends a held head that no
// body followed (HEAD, 204, an empty body).
// Used by one worker thread at a time (not thread-safe).
#pragma once

#include <httplib.h>
#include <sys/socket.h>
#include <sys/uio.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "server/http/worker_load.h"

namespace clearsky::server {

struct ConnectionLimits {
  std::chrono::milliseconds read_timeout{10000};
  std::chrono::milliseconds write_timeout{30000};
  std::chrono::milliseconds keep_alive_timeout{5000};
  std::chrono::milliseconds head_timeout{10000};
  // How long a head may take while workers are scarce.
  std::chrono::milliseconds scarce_head_grace{1000};
  std::size_t min_send_rate_bytes_per_s = 1024;  // 0: no minimum
  std::chrono::milliseconds send_rate_grace{10000};
};

class ConnectionStream final : public httplib::Stream {
 public:
  using Clock = std::chrono::steady_clock;

  // The connection keeps sock (closed by its owner). load must outlive the stream. While
  // stopping() is true (the server stops), waits for a request or for a head give up.
  ConnectionStream(socket_t sock, const ConnectionLimits& limits, const WorkerLoad& load,
                   std::function<bool()> stopping);

  // Waits for the first byte of the next request (true), or gives up: keep-alive timeout,
  // closed connection, workers scarce (for the first request of the connection: after the
  // scarce head grace), or the server stopping.
  bool wait_for_request(bool first);
  // The head of a request starts (its clock runs from here) and ends (setup of the request).
  void begin_request();
  void end_head();
  // The head of the request in progress arrived whole.
  bool head_complete() const { return head_complete_; }
  // Sends what the answer in progress still holds back (a head without a body); false when the
  // connection failed or timed out.
  bool flush_answer();

  bool is_readable() const override;
  bool is_writable() const override;
  ssize_t read(char* ptr, std::size_t size) override;
  ssize_t write(const char* ptr, std::size_t size) override;
  void get_remote_ip_and_port(std::string& ip, int& port) const override;
  void get_local_ip_and_port(std::string& ip, int& port) const override;
  socket_t socket() const override;

 private:
  enum class Wait { ready, timeout, failed };
  // Waits for events until deadline, in slices so that scarcity and the send rate are
  // re-checked; give_up is asked after each slice.
  Wait wait(short events, Clock::time_point deadline,
            const std::function<bool(Clock::time_point)>& give_up) const;
  // The send-rate deadline of the answer in progress.
  Clock::time_point send_rate_deadline() const;
  // One sendmsg(2) of the given parts, waiting for room within the write deadlines: the number
  // of bytes sent (at least one when size > 0), or -1.
  ssize_t send_parts(const iovec* parts, std::size_t count);

  socket_t sock_;
  ConnectionLimits limits_;
  const WorkerLoad& load_;
  std::function<bool()> stopping_;
  std::vector<char> buffer_;
  std::size_t buffer_begin_ = 0, buffer_end_ = 0;
  bool in_head_ = false;
  bool head_complete_ = false;
  Clock::time_point head_start_{};
  bool answering_ = false;
  Clock::time_point answer_start_{};
  std::size_t answer_bytes_ = 0;
  // The answer's head, not sent yet (see the class comment).
  std::string held_head_;
  // The connection's two addresses, asked of the kernel once: cpp-httplib asks for both on every
  // request, two system calls and two getnameinfo(3) each time on a keep-alive connection.
  struct Address {
    bool known = false;
    std::string ip;
    int port = 0;
  };
  mutable Address remote_, local_;
  // getpeername(2) or getsockname(2).
  using AskAddress = int (*)(int, sockaddr*, socklen_t*);
  // The address, asked of the kernel with ask on the first call.
  void known_address(Address& address, AskAddress ask, std::string& ip, int& port) const;
};

}  // namespace clearsky::server
