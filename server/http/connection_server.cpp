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

bool ConnectionServer::process_and_close_socket(socket_t sock) {
  const auto stopping = [this] { return svr_sock_ == INVALID_SOCKET; };
  ConnectionStream stream(sock, limits_, load_, stopping);
  bool ok = false;
  for (std::size_t left = keep_alive_max_count_; left > 0 && !stopping(); --left) {
    if (!stream.wait_for_request(left == keep_alive_max_count_)) break;
    stream.begin_request();
    // While workers are scarce, the answer ends the connection: the worker goes to a
    // connection waiting for one (the client reconnects at the back of the queue).
    const bool last = left == 1 || load_.scarce();
    bool closed = false;
    ok = process_request(stream, last, closed, [&stream](httplib::Request&) { stream.end_head(); });
    // A head that did not arrive whole (too slow, or not HTTP) was answered 400: what follows
    // on the connection cannot be trusted to start a request.
    if (!ok || closed || last || !stream.head_complete()) break;
  }
  ::shutdown(sock, SHUT_RDWR);
  ::close(sock);
  return ok;
}

}  // namespace clearsky::server
