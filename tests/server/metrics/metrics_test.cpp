// Request metrics (server/metrics/metrics.h): each (endpoint, model, status) is its own counter
// series, observed again through the series kept from its first request; the duration
// histogram is per (endpoint, model); no model is labelled "none".
#include "server/metrics/metrics.h"

#include <gtest/gtest.h>

#include <string>

namespace clearsky::server {
namespace {

bool has_line(const std::string& text, const std::string& line) {
  return text.find(line + "\n") != std::string::npos;
}

TEST(Metrics, RequestSeriesCountEachEndpointModelAndStatus) {
  Metrics metrics;
  metrics.observe_request("/v1/radiance", "preetham", 200, 0.001);
  metrics.observe_request("/v1/radiance", "preetham", 200, 0.002);
  metrics.observe_request("/v1/radiance", "preetham", 400, 0.001);
  metrics.observe_request("/healthz", "", 200, 0.0001);
  const std::string text = metrics.scrape({});
  EXPECT_TRUE(has_line(
      text,
      R"(clearsky_http_requests_total{endpoint="/v1/radiance",model="preetham",status="200"} 2)"))
      << text;
  EXPECT_TRUE(has_line(
      text,
      R"(clearsky_http_requests_total{endpoint="/v1/radiance",model="preetham",status="400"} 1)"));
  EXPECT_TRUE(has_line(
      text, R"(clearsky_http_requests_total{endpoint="/healthz",model="none",status="200"} 1)"));
  EXPECT_TRUE(has_line(
      text,
      R"(clearsky_http_request_duration_seconds_count{endpoint="/v1/radiance",model="preetham"} 3)"));
}

}  // namespace
}  // namespace clearsky::server
