// The per-request bookkeeping around every answer (docs/http-api.md): finding the route of a
// path in the route table, the strong ETag of a typical 1.3 KB radiance answer, counting the
// request in the metrics, and the whole /v1/radiance handler on the server's TableStore (its
// parameters, quality level, model lookup and JSON answer) on Preetham and Hosek. Each was
// measured with callgrind on a running server before it was made cheaper (CHANGELOG); these
// keep the figures in view.
#include <benchmark/benchmark.h>
#include <prometheus/counter.h>
#include <prometheus/registry.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "api/encode/json_text.h"
#include "api/handlers/handlers.h"
#include "api/http/cache_policy.h"
#include "api/routes/route_match.h"
#include "models/registry.h"
#include "server/metrics/metrics.h"
#include "server/tables/table_store.h"

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

// The 31 radiance values of a Hosek answer (W/(m2.sr.nm), 17 significant digits as most are),
// written as JSON numbers: the answer's text writer (api/encode/json_text.h) against
// nlohmann-json's dump() of the same array, the DOM path it replaced.
const std::vector<double>& radiance_like_values() {
  static const std::vector<double> values = {
      0.11102259823667522,  0.09957851136712426,  0.08858210001615695,  0.11865449378731069,
      0.13220523888205976,  0.11731941379877553,  0.11241662357336954,  0.12112001627587615,
      0.11557380254563465,  0.10541053884078566,  0.09500530134525775,  0.08892103447891254,
      0.081765132529082,    0.07186786504074857,  0.06988328278328704,  0.06555209663433992,
      0.06145173151295879,  0.05620683346761806,  0.05272055610000907,  0.047299443147099024,
      0.043210762372330846, 0.039169021032813216, 0.036442255872816506, 0.033425870021094414,
      0.03050255962723888,  0.027434850537733417, 0.02580709268588639,  0.023380546114338104,
      0.02193121036292181,  0.021100465819618233, 0.02050840965035823};
  return values;
}

void BM_JsonNumbers_RadianceSpectrum(benchmark::State& state) {
  std::string out;
  out.reserve(1024);
  for (auto _ : state) {
    out.clear();
    api::append_json_number_array(out, radiance_like_values());
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() *
                          static_cast<std::int64_t>(radiance_like_values().size()));
}
BENCHMARK(BM_JsonNumbers_RadianceSpectrum);

void BM_JsonNumbers_RadianceSpectrum_NlohmannDump_Baseline(benchmark::State& state) {
  const nlohmann::json array = radiance_like_values();
  for (auto _ : state) benchmark::DoNotOptimize(array.dump());
  state.SetItemsProcessed(state.iterations() *
                          static_cast<std::int64_t>(radiance_like_values().size()));
}
BENCHMARK(BM_JsonNumbers_RadianceSpectrum_NlohmannDump_Baseline);

// GET /v1/radiance of one view on Preetham's 40 bins, as a server answers it (the HTTP
// transport aside). Whether a standard answer could come from the draft tables was decided by
// comparing the two configurations' canonical strings, a third of this handler's instructions
// (callgrind, 274k to 175k per answer); the options are compared now.
void BM_RadianceHandler_Preetham(benchmark::State& state) {
  server::TableStore store({*find_model("preetham")}, server::TableStore::Options{});
  const api::ApiContext context{store, api::Limits{}};
  const api::ApiRequest request{"GET",
                                "/v1/radiance",
                                {{"model", "preetham"},
                                 {"sun_zenith", "30"},
                                 {"sun_azimuth", "0"},
                                 {"view_zenith", "45"},
                                 {"view_azimuth", "90"}},
                                ""};
  benchmark::DoNotOptimize(api::radiance(context, request));  // the model built once
  for (auto _ : state) benchmark::DoNotOptimize(api::radiance(context, request));
}
BENCHMARK(BM_RadianceHandler_Preetham)->Unit(benchmark::kMicrosecond);

// The same on Hosek, the request tests/bench/load.sh sends (its sun state is computed for every
// request: most of what is left). Its standard level has a draft fallback, whose lookup wrote
// the configuration's canonical text through ostringstreams on every request (a sixth of the
// request's instructions in callgrind of a server under wrk) until the default configuration's
// text was reused; and the JSON answer was an nlohmann DOM (api/encode/radiance_json.h).
void BM_RadianceHandler_Hosek(benchmark::State& state) {
  server::TableStore store({*find_model("hosek")}, server::TableStore::Options{});
  const api::ApiContext context{store, api::Limits{}};
  const api::ApiRequest request{"GET",
                                "/v1/radiance",
                                {{"model", "hosek"},
                                 {"sun_zenith", "40"},
                                 {"sun_azimuth", "135"},
                                 {"view_zenith", "50"},
                                 {"view_azimuth", "200"}},
                                ""};
  benchmark::DoNotOptimize(api::radiance(context, request));  // the model built once
  for (auto _ : state) benchmark::DoNotOptimize(api::radiance(context, request));
}
BENCHMARK(BM_RadianceHandler_Hosek)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace clearsky
