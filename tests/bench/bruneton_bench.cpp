// Bruneton 2008 / Elek 2010: precomputation time (paper resolution and cheaper settings, with
// their RMSE on the 15 public captures: run-time-vs-error points), loading the tables from a
// cache blob, and the O(1) queries (one 40-wavelength radiance, the 81-direction batch of the
// evaluation, irradiance lookups, aerial perspective).
//
// The paper-resolution tables are cached in ./bruneton_bench_cache/ (a plain file TableCache
// written for this benchmark), so that query benchmarks start in about a second after the
// first run.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "models/bruneton/bruneton.h"
#include "models/evaluation/evaluate_model.h"
#include "models/registry.h"
#include "tests/bench/peak_resident.h"
#include "tests/support/public_captures.h"

namespace clearsky {
namespace {

class FileTableCache : public TableCache {
 public:
  explicit FileTableCache(std::filesystem::path dir) : dir_(std::move(dir)) {
    std::filesystem::create_directories(dir_);
  }
  std::optional<std::string> load(const std::string& key) const override {
    std::ifstream in(dir_ / key, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
  }
  void store(const std::string& key, std::string_view bytes) const override {
    const auto tmp = dir_ / (key + ".tmp");
    {
      std::ofstream out(tmp, std::ios::binary);
      out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      if (!out) return;
    }
    std::filesystem::rename(tmp, dir_ / key);
  }
  std::filesystem::path path(const std::string& key) const { return dir_ / key; }

 private:
  std::filesystem::path dir_;
};

const FileTableCache& file_cache() {
  static const FileTableCache cache("bruneton_bench_cache");
  return cache;
}

const BrunetonModel& paper_model() {
  static const std::shared_ptr<const BrunetonModel> model = [] {
    PrecomputeContext context;
    context.cache = &file_cache();
    return BrunetonModel::create(bruneton_descriptor(), ModelConfig{}, context);
  }();
  return *model;
}

// The 81 directions of the evaluation: rings at zenith 0, 18.08, 36.63, 56.25, 77.88 degrees
// with 1, 8, 16, 24, 32 samples.
std::vector<ViewDirection> evaluation_directions() {
  std::vector<ViewDirection> views = {{0.0, 0.0}};
  const double zeniths[] = {18.0813, 36.6335, 56.2510, 77.8849};
  const int counts[] = {8, 16, 24, 32};
  for (int ring = 0; ring < 4; ++ring) {
    for (int i = 0; i < counts[ring]; ++i)
      views.push_back({degrees_to_radians(zeniths[ring]), 2.0 * kPi * i / counts[ring]});
  }
  return views;
}

// A fresh precomputation: the tables of paper_model(), alive in this process, are not reused.
PrecomputeContext fresh_build() {
  PrecomputeContext context;
  context.reuse_live_tables = false;
  return context;
}

// peak_MB: the process's peak resident memory during the build (reset before it), which the
// precomputation's intermediate tables set (docs/tables-and-memory.md).
void BM_BrunetonPrecomputePaper(benchmark::State& state) {
  for (auto _ : state) {
    bench::reset_peak_resident();
    const auto model = BrunetonModel::create(bruneton_descriptor(), ModelConfig{}, fresh_build());
    benchmark::DoNotOptimize(model.get());
    state.counters["table_MB"] = static_cast<double>(model->table_bytes()) / 1e6;
    state.counters["peak_MB"] = static_cast<double>(bench::peak_resident_bytes()) / 1e6;
  }
  state.SetLabel("40 wavelengths, 32x128x32x8, 4 orders, all cores");
}
BENCHMARK(BM_BrunetonPrecomputePaper)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

// Args: r, mu, mu_s, nu, orders. Reports the precomputation time and the RMSE on the 15
// public captures (when the measurement data is present, README.md "Data").
void BM_BrunetonSettings(benchmark::State& state) {
  ModelConfig config;
  config.options["table_r_size"] = static_cast<double>(state.range(0));
  config.options["table_mu_size"] = static_cast<double>(state.range(1));
  config.options["table_mu_s_size"] = static_cast<double>(state.range(2));
  config.options["table_nu_size"] = static_cast<double>(state.range(3));
  config.options["scattering_orders"] = static_cast<double>(state.range(4));
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const auto model = BrunetonModel::create(bruneton_descriptor(), config, fresh_build());
    state.counters["precompute_s"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.counters["table_MB"] = static_cast<double>(model->table_bytes()) / 1e6;
    state.PauseTiming();
    try {
      state.counters["rmse"] = evaluate_sky_model(*model, testing::public_captures()).rmse;
    } catch (const std::exception& e) {
      state.SetLabel(std::string("no RMSE: ") + e.what());
    }
    state.ResumeTiming();
  }
}
BENCHMARK(BM_BrunetonSettings)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime()
    ->Args({32, 128, 32, 8, 4})
    ->Args({32, 128, 32, 8, 3})
    ->Args({32, 128, 32, 8, 2})
    ->Args({32, 128, 32, 8, 1})
    ->Args({16, 128, 32, 8, 4})
    ->Args({32, 64, 16, 8, 4})
    ->Args({16, 64, 16, 4, 4})
    ->Args({8, 32, 8, 4, 4});

void BM_BrunetonLoadBlob(benchmark::State& state) {
  const BrunetonModel& model = paper_model();
  const std::string description = BrunetonModel::table_description(ModelConfig{});
  const std::string blob = bruneton::serialise_tables(model.tables(), description);
  for (auto _ : state) {
    auto tables = bruneton::deserialise_tables(blob, description);
    benchmark::DoNotOptimize(tables);
  }
  state.counters["blob_MB"] = static_cast<double>(blob.size()) / 1e6;
}
BENCHMARK(BM_BrunetonLoadBlob)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_BrunetonLoadFromDiskCache(benchmark::State& state) {
  paper_model();  // makes sure the file exists
  for (auto _ : state) {
    PrecomputeContext context = fresh_build();
    context.cache = &file_cache();
    const auto model = BrunetonModel::create(bruneton_descriptor(), ModelConfig{}, context);
    if (!model->loaded_from_cache()) state.SkipWithError("the cache file was not used");
    benchmark::DoNotOptimize(model.get());
  }
}
BENCHMARK(BM_BrunetonLoadFromDiskCache)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3)
    ->UseRealTime();

void BM_BrunetonRadiance(benchmark::State& state) {
  const BrunetonModel& model = paper_model();
  const auto sun = model.prepare_sun({degrees_to_radians(35.0), degrees_to_radians(120.0)});
  const std::vector<ViewDirection> view = {{degrees_to_radians(50.0), degrees_to_radians(200.0)}};
  SpectralBatch out;
  for (auto _ : state) {
    model.sky_radiance(*sun, {0.0}, view, out);
    benchmark::DoNotOptimize(out.values.data());
  }
  state.SetLabel(bruneton::using_avx2_kernels() ? "40 wavelengths, AVX2"
                                                : "40 wavelengths, portable");
}
BENCHMARK(BM_BrunetonRadiance)->Unit(benchmark::kNanosecond);

void BM_BrunetonRadianceBatch81(benchmark::State& state) {
  const BrunetonModel& model = paper_model();
  const auto sun = model.prepare_sun({degrees_to_radians(35.0), degrees_to_radians(120.0)});
  const std::vector<ViewDirection> views = evaluation_directions();
  SpectralBatch out;
  for (auto _ : state) {
    model.sky_radiance(*sun, {0.0}, views, out);
    benchmark::DoNotOptimize(out.values.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(views.size()));
}
BENCHMARK(BM_BrunetonRadianceBatch81)->Unit(benchmark::kMicrosecond);

void BM_BrunetonScatteringLookup(benchmark::State& state) {
  const bruneton::Tables& t = paper_model().tables();
  std::vector<float> out(t.stride);
  double mu = 0.3;
  for (auto _ : state) {
    t.scattering(t.geometry.bottom_m, mu, 0.8, 0.5, 0.7, out.data());
    benchmark::DoNotOptimize(out.data());
    mu = mu > 0.9 ? 0.3 : mu + 0.001;
  }
}
BENCHMARK(BM_BrunetonScatteringLookup)->Unit(benchmark::kNanosecond);

void BM_BrunetonSkyIrradiance(benchmark::State& state) {
  const BrunetonModel& model = paper_model();
  const auto sun = model.prepare_sun({degrees_to_radians(35.0), 0.0});
  for (auto _ : state) benchmark::DoNotOptimize(model.sky_irradiance(*sun, {0.0}));
  state.SetLabel("horizontal plane, from the irradiance table");
}
BENCHMARK(BM_BrunetonSkyIrradiance)->Unit(benchmark::kNanosecond);

void BM_BrunetonSunIrradiance(benchmark::State& state) {
  const BrunetonModel& model = paper_model();
  const auto sun = model.prepare_sun({degrees_to_radians(35.0), 0.0});
  for (auto _ : state) benchmark::DoNotOptimize(model.sun_irradiance(*sun, {0.0}));
}
BENCHMARK(BM_BrunetonSunIrradiance)->Unit(benchmark::kNanosecond);

void BM_BrunetonAerialPerspective(benchmark::State& state) {
  const BrunetonModel& model = paper_model();
  const auto sun = model.prepare_sun({degrees_to_radians(35.0), 0.0});
  const ViewDirection view{degrees_to_radians(85.0), 1.0};
  for (auto _ : state)
    benchmark::DoNotOptimize(model.aerial_perspective(*sun, {100.0}, view, 15e3));
}
BENCHMARK(BM_BrunetonAerialPerspective)->Unit(benchmark::kNanosecond);

}  // namespace
}  // namespace clearsky
