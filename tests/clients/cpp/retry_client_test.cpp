// The client's retries against a real 503 with Retry-After: a `clearsky serve` with
// --build-wait-ms 0 answers a request for a configuration whose tables are not built yet 503
// model_not_ready with Retry-After (server/tables/table_store.cpp; docs/http-api.md "Errors")
// at once; Nishita93's tables take about a second to build (its README), so the first answer
// is always that 503, and the client asks again until the tables are there. With no retries
// allowed, or a Retry-After above the client's bound, the 503 is the Error.
#include <clearsky/client/client.h>
#include <gtest/gtest.h>

#include <vector>

#include "tests/clients/cpp/client_server.h"

namespace clearsky::client {
namespace {

class RetryClient : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    server_ =
        new testing::ClientServer({"--build-wait-ms", "0", "--retry-after", "1"}, "nishita93");
    ASSERT_GT(server_->port(), 0) << server_->log();
    ASSERT_TRUE(server_->ready()) << server_->log();
  }
  static void TearDownTestSuite() {
    delete server_;
    server_ = nullptr;
  }
  // A radiance request whose tables (a new Angstrom exponent) no request built before.
  static RadianceRequest new_configuration(double alpha) {
    RadianceRequest request;
    request.model = "nishita93";
    request.sun = SunAngles{40, 100};
    request.view = {60, 10};
    request.parameters["alpha"] = alpha;
    return request;
  }
  static testing::ClientServer* server_;
};
testing::ClientServer* RetryClient::server_ = nullptr;

TEST_F(RetryClient, A503WithRetryAfterIsAskedAgainUntilAnswered) {
  ClientOptions options = server_->options();
  // Generous for a loaded machine or a sanitizer build: the tables take seconds there.
  options.max_retries = 300;
  std::vector<RetryNotice> notices;
  options.on_retry = [&](const RetryNotice& notice) { notices.push_back(notice); };
  const RadianceResult result = Client(options).radiance(new_configuration(1.1));
  ASSERT_EQ(result.samples.size(), 1u);
  EXPECT_GT(result.samples[0].radiance_w_m2_sr_nm[0], 0);
  ASSERT_GE(notices.size(), 1u) << server_->log();
  EXPECT_EQ(notices[0].attempt, 1);
  EXPECT_EQ(notices[0].status, 503);
  EXPECT_EQ(notices[0].code, "model_not_ready");
  EXPECT_EQ(notices[0].wait_s, 1);
}

TEST_F(RetryClient, TheRetriesAreBounded) {
  ClientOptions options = server_->options();
  options.max_retries = 0;
  int notices = 0;
  options.on_retry = [&](const RetryNotice&) { ++notices; };
  try {
    Client(options).radiance(new_configuration(1.2));
    FAIL() << "tables were ready at once: " << server_->log();
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 503);
    EXPECT_EQ(e.code(), "model_not_ready");
    EXPECT_EQ(e.parameter(), "model");
    EXPECT_EQ(e.retry_after_s(), 1);
  }
  EXPECT_EQ(notices, 0);

  // A Retry-After above the client's bound is not waited for.
  options.max_retries = 5;
  options.max_retry_wait_s = 0;
  try {
    Client(options).radiance(new_configuration(1.3));
    FAIL() << "tables were ready at once: " << server_->log();
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 503);
    EXPECT_EQ(e.retry_after_s(), 1);
  }
  EXPECT_EQ(notices, 0);
}

}  // namespace
}  // namespace clearsky::client
