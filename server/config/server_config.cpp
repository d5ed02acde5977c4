// Resolution of defaults that depend on the machine.
#include "server/config/server_config.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace clearsky::server {

unsigned ServerConfig::worker_threads() const { return threads > 0 ? threads : 512u; }

void ServerConfig::check_connection_slots() const {
  // Descriptors below 1024 for every connection a worker or the queue holds, with 128 left
  // for the listening socket, the database, the cache, the log and the accepting thread.
  constexpr std::size_t kConnectionSlots = 1024 - 128;
  if (worker_threads() + max_queued > kConnectionSlots)
    throw std::invalid_argument("threads + max-queued is " +
                                std::to_string(worker_threads() + max_queued) + ", above " +
                                std::to_string(kConnectionSlots) +
                                ": cpp-httplib 0.11.4 (select(2)) answers 500 on connections "
                                "whose descriptor is 1024 or more");
}

std::size_t ServerConfig::body_limit_bytes() const {
  return std::max(payload_max_bytes, max_upload_bytes);
}

}  // namespace clearsky::server
