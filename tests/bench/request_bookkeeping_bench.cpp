// The per-request bookkeeping around every answer (docs/http-api.md): finding the route of a
// path in the route table, the strong ETag of a typical 1.3 KB radiance answer, and counting
// the request in the metrics. Each was measured with callgrind on a running server before it
// was made cheaper (CHANGELOG); these keep the figures in view.
#include <benchmark/benchmark.h>
#include <prometheus/counter.h>
#include <prometheus/registry.h>

#include <string>

#include "api/http/cache_policy.h"
#include "api/routes/route_match.h"
#include "server/metrics/metrics.h"

namespace clearsky {
namespace {

void BM_MatchRoute_Radiance(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(api::match_route("GET", "/v1/radiance"));
}
BENCHMARK(BM_MatchRoute_Radiance);

void BM_MatchRoute_PathParameter(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(api::match_route("GET", "/v1/evaluations/42"));
}
BENCHMARK(BM_MatchRoute_PathParameter);

void BM_StrongEtag_RadianceAnswer(benchmark::State& state) {
  const std::string body(1325, 'x');
  for (auto _ : state) benchmark::DoNotOptimize(api::strong_etag(body));
}
BENCHMARK(BM_StrongEtag_RadianceAnswer);

void BM_Metrics_ObserveRequest(benchmark::State& state) {
  server::Metrics metrics;
  const std::string endpoint = "/v1/radiance";
  const std::string model = "preetham";
  for (auto _ : state) metrics.observe_request(endpoint, model, 200, 0.0004);
}
BENCHMARK(BM_Metrics_ObserveRequest);

// The baseline the metrics were measured against: a counter series looked up through its label
// map on every request, as prometheus-cpp's Family::Add does.
void BM_Metrics_FamilyAddEveryRequest_Baseline(benchmark::State& state) {
  prometheus::Registry registry;
  auto& family =
      prometheus::BuildCounter().Name("requests_total").Help("baseline").Register(registry);
  const std::string endpoint = "/v1/radiance";
  const std::string model = "preetham";
  for (auto _ : state)
    family.Add({{"endpoint", endpoint}, {"model", model}, {"status", std::to_string(200)}})
        .Increment();
}
BENCHMARK(BM_Metrics_FamilyAddEveryRequest_Baseline);

}  // namespace
}  // namespace clearsky
