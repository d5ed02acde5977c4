// cpp-httplib's Server with its connections served by ConnectionStream: the per-connection
// loop (keep-alive, then one request after another) is this class's, so that a connection
// obeys the head deadline, the send rate and the worker scarcity of docs/deployment.md
// "Limits in the server"; parsing, routing and answering stay cpp-httplib's (process_request,
// the library's own extension point, as its SSL server uses it). The worker pool is an
// ElasticTaskQueue publishing into load().
// Draining (docs/deploy.md "Graceful drain"): after begin_drain() every answer ends its
// connection; once the listening socket is closed (stop()), idle connections end, a connection
// already accepted still gets its first request answered, and requests in flight finish;
// cut_connections() ends those left when the drain's time is up.
#pragma once

#include <httplib.h>

#include <atomic>
#include <mutex>
#include <set>

#include "server/http/connection_stream.h"
#include "server/http/elastic_task_queue.h"
#include "server/http/worker_load.h"

namespace clearsky::server {

class ConnectionServer final : public httplib::Server {
 public:
  ConnectionServer(const ConnectionLimits& limits, const ElasticTaskQueue::Options& pool);

  const WorkerLoad& load() const { return load_; }

  // From now on each answer carries Connection: close. Thread-safe.
  void begin_drain() { draining_ = true; }
  bool draining() const { return draining_; }
  // Shuts down (shutdown(2)) every connection still open; their workers end at their next read
  // or write. Returns how many. Thread-safe.
  std::size_t cut_connections();

 private:
  bool process_and_close_socket(socket_t sock) override;

  ConnectionLimits limits_;
  WorkerLoad load_;
  std::atomic<bool> draining_{false};
  // The sockets of the connections being served: a socket leaves the set before it is closed,
  // so cut_connections() never touches a descriptor the process has reused.
  std::mutex connections_mutex_;
  std::set<socket_t> connections_;
};

}  // namespace clearsky::server
