// cpp-httplib's Server with its connections served by ConnectionStream: the per-connection
// loop (keep-alive, then one request after another) is this class's, so that a connection
// obeys the head deadline, the send rate and the worker scarcity of docs/deployment.md
// "Limits in the server"; parsing, routing and answering stay cpp-httplib's (process_request,
// the library's own extension point, as its SSL server uses it). The worker pool is an
// ElasticTaskQueue publishing into load().
#pragma once

#include <httplib.h>

#include "server/http/connection_stream.h"
#include "server/http/elastic_task_queue.h"
#include "server/http/worker_load.h"

namespace clearsky::server {

class ConnectionServer final : public httplib::Server {
 public:
  ConnectionServer(const ConnectionLimits& limits, const ElasticTaskQueue::Options& pool);

  const WorkerLoad& load() const { return load_; }

 private:
  bool process_and_close_socket(socket_t sock) override;

  ConnectionLimits limits_;
  WorkerLoad load_;
};

}  // namespace clearsky::server
