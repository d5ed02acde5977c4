// ServerConfig's connection slots (docs/deployment.md "Why connections can starve the server"):
// workers plus queued connections stay below the descriptors cpp-httplib's select(2) serves;
// the documented default of the evaluation workers.
#include "server/config/server_config.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>

namespace clearsky::server {
namespace {

TEST(ServerConfig, ConnectionSlotsStayBelowTheDescriptorLimit) {
  ServerConfig config;
  EXPECT_EQ(config.worker_threads(), 512u);
  EXPECT_NO_THROW(config.check_connection_slots());
  config.threads = 640;
  config.max_queued = 256;
  EXPECT_NO_THROW(config.check_connection_slots());
  config.max_queued = 257;
  EXPECT_THROW(config.check_connection_slots(), std::invalid_argument);
  config.threads = 900;
  config.max_queued = 1;
  EXPECT_THROW(config.check_connection_slots(), std::invalid_argument);
}

TEST(ServerConfig, TwoEvaluationWorkersWhereTwoCoresAllow) {
  // docs/data-api.md "Evaluations": min(2, cores), at least one.
  const unsigned cores = std::thread::hardware_concurrency();
  const ServerConfig config;
  EXPECT_EQ(config.evaluation_workers, cores >= 2 ? 2u : 1u);
}

}  // namespace
}  // namespace clearsky::server
