// GET /v1/irradiance/series against its baseline (docs/building-energy.md "Irradiance time
// series"): a whole year hourly (8,784 steps in 2024) for one site (Paris) and three planes
// (30:180, 90:180, 90:90) with Bruneton at its standard (paper) setting, computed
//  - as one series (the handler, its rows streamed into a counting sink), and
//  - as 8,784 x 3 independent GET /v1/irradiance requests (the handler, one plane each), what
//    a client without the series route does.
// The paper-resolution tables come from the server's on-disk table cache
// (server/cache/file_table_cache.h) in $CLEARSKY_BENCH_CACHE_DIR, default ./series_bench_cache
// (written on the first run; a `clearsky serve --cache-dir` directory that holds Bruneton's
// default tables serves as well), so the runs time the queries, not the precomputation.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <map>
#include <mutex>

#include "api/encode/iso8601_time.h"
#include "api/handlers/handlers.h"
#include "models/registry.h"
#include "server/cache/file_table_cache.h"

namespace clearsky {
namespace {

// The registered models, each configuration built once with the file cache.
class CachedProvider final : public api::ModelProvider {
 public:
  std::span<const ModelFactory> factories() const override { return registered_models(); }
  using api::ModelProvider::model;
  std::shared_ptr<const SkyModel> model(const ModelFactory& factory, const ModelConfig& config,
                                        const api::ModelRequester&) const override {
    std::lock_guard lock(mutex_);
    auto& slot = built_[factory.descriptor->id + "|" + config.canonical_string()];
    if (!slot) {
      PrecomputeContext context;
      context.cache = &cache_;
      slot = factory.create(config, context);
    }
    return slot;
  }
  api::ModelState default_state(const ModelFactory&) const override {
    api::ModelState s;
    s.status = api::ModelState::Status::ready;
    s.progress = 1.0;
    return s;
  }

 private:
  server::FileTableCache cache_{std::getenv("CLEARSKY_BENCH_CACHE_DIR") != nullptr
                                    ? std::getenv("CLEARSKY_BENCH_CACHE_DIR")
                                    : "series_bench_cache"};
  mutable std::mutex mutex_;
  mutable std::map<std::string, std::shared_ptr<const SkyModel>> built_;
};

const CachedProvider& provider() {
  static const CachedProvider p;
  return p;
}

using Query = std::vector<std::pair<std::string, std::string>>;
const Query kPlace = {{"model", "bruneton"}, {"lat", "48.85"}, {"lon", "2.35"}};
constexpr double kStart2024 = 1704067200.0;  // 2024-01-01T00:00:00Z
constexpr int kHours2024 = 8784;

// A daytime request, to build (or load) the tables before timing.
Query noon() {
  Query q = kPlace;
  q.emplace_back("time", "2024-06-21T12:00:00Z");
  return q;
}

void BM_IrradianceSeriesYearThreePlanes(benchmark::State& state) {
  const api::Limits limits;
  const api::ApiContext context{provider(), limits};
  Query q = kPlace;
  q.insert(q.end(), {{"start", "2024-01-01T00:00:00Z"},
                     {"end", "2024-12-31T23:00:00Z"},
                     {"step", "PT1H"},
                     {"planes", "30:180,90:180,90:90"},
                     {"format", "csv"}});
  (void)api::irradiance(context, {"GET", "/v1/irradiance", noon(), ""});  // build the tables
  std::size_t bytes = 0;
  for (auto _ : state) {
    const api::ApiResponse r =
        api::irradiance_series(context, {"GET", "/v1/irradiance/series", q, ""});
    bytes = 0;
    r.stream([&](const char*, std::size_t size) {
      bytes += size;
      return true;
    });
  }
  state.counters["steps"] = kHours2024;
  state.counters["bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_IrradianceSeriesYearThreePlanes)->Unit(benchmark::kMillisecond)->Iterations(1);

// The baseline: one GET /v1/irradiance per hour and plane (night hours too, as a client
// would send them; the model answers 422 for them, which is caught and counted).
void BM_IndependentIrradianceYearThreePlanes(benchmark::State& state) {
  const api::Limits limits;
  const api::ApiContext context{provider(), limits};
  (void)api::irradiance(context, {"GET", "/v1/irradiance", noon(), ""});
  const std::pair<const char*, const char*> planes[] = {{"30", "180"}, {"90", "180"}, {"90", "90"}};
  std::size_t refused = 0;
  for (auto _ : state) {
    refused = 0;
    for (int hour = 0; hour < kHours2024; ++hour) {
      const std::string time = api::format_iso8601_time(kStart2024 + 3600.0 * hour, 0, true);
      for (const auto& [tilt, azimuth] : planes) {
        Query q = kPlace;
        q.insert(q.end(), {{"time", time}, {"tilt", tilt}, {"surface_azimuth", azimuth}});
        try {
          benchmark::DoNotOptimize(api::irradiance(context, {"GET", "/v1/irradiance", q, ""}));
        } catch (const api::ApiError&) {
          ++refused;
        }
      }
    }
  }
  state.counters["requests"] = kHours2024 * 3;
  state.counters["refused_night"] = static_cast<double>(refused);
}
BENCHMARK(BM_IndependentIrradianceYearThreePlanes)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace clearsky
