// The keep-alive loop of one connection.
#include "server/http/connection_server.h"

#include <sys/socket.h>
#include <unistd.h>

namespace clearsky::server {

ConnectionServer::ConnectionServer(const ConnectionLimits& limits,
                                   const ElasticTaskQueue::Options& pool)
    : limits_(limits), load_(pool.max_workers) {
  new_task_queue = [this, pool] { return new ElasticTaskQueue(pool, load_); };
}

std::size_t ConnectionServer::cut_connections() {
  const std::lock_guard lock(connections_mutex_);
  for (const socket_t sock : connections_) ::shutdown(sock, SHUT_RDWR);
  return connections_.size();
}

bool ConnectionServer::process_and_close_socket(socket_t sock) {
  {
    const std::lock_guard lock(connections_mutex_);
    connections_.insert(sock);
  }
  const auto stopping = [this] { return svr_sock_ == INVALID_SOCKET; };
  ConnectionStream stream(sock, limits_, load_, stopping);
  bool ok = false;
  for (std::size_t left = keep_alive_max_count_; left > 0; --left) {
    const bool first = left == keep_alive_max_count_;
    // A stopping server still answers the request a connection it accepted has already sent
    // (wait_for_request gives up at once when there is none): a client, or a proxy, never
    // loses a request to the stop.
    if (!first && stopping()) break;
    if (!stream.wait_for_request(first)) break;
    stream.begin_request();
    // While workers are scarce, the answer ends the connection: the worker goes to a
    // connection waiting for one (the client reconnects at the back of the queue). While the
    // server drains, so does every answer: the client reconnects, to another replica.
    const bool last = left == 1 || load_.scarce() || draining_ || stopping();
    bool closed = false;
    ok = process_request(stream, last, closed, [&stream](httplib::Request&) { stream.end_head(); });
    // A head that no body followed is still held back (ConnectionStream).
    ok = stream.flush_answer() && ok;
    // A head that did not arrive whole (too slow, or not HTTP) was answered 400: what follows
    // on the connection cannot be trusted to start a request.
    if (!ok || closed || last || !stream.head_complete()) break;
  }
  {
    const std::lock_guard lock(connections_mutex_);
    connections_.erase(sock);
  }
  ::shutdown(sock, SHUT_RDWR);
  ::close(sock);
  return ok;
}

}  // namespace clearsky::server
