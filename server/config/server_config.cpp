// Resolution of defaults that depend on the machine.
#include "server/config/server_config.h"

#include <algorithm>
#include <thread>

namespace clearsky::server {

unsigned ServerConfig::worker_threads() const {
  if (threads > 0) return threads;
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  return std::max(64u, 32u * cores);
}

std::size_t ServerConfig::body_limit_bytes() const {
  return std::max(payload_max_bytes, max_upload_bytes);
}

}  // namespace clearsky::server
