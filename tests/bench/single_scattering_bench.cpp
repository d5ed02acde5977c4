// Speed of the single-scattering models at the paper's resolution and at cheaper and finer
// settings (points of the run-time-vs-error curve; the RMSE of each setting is printed by
// tests/accuracy/single_scattering/single_scattering_accuracy_test.cpp): one 40-wavelength
// radiance, a batch of the 81 measured directions, the sky irradiance at the ground, and
// Nishita93's precomputation. Single thread. Targets: Nishita93 < 5 us per radiance
// and < 10 ms per sky irradiance (the study's code: 23 us, 232 ms); O'Neal < 1 us.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "models/nishita93/nishita93.h"
#include "models/nishita93/nishita93_tables.h"
#include "models/oneal/oneal.h"

namespace clearsky {
namespace {

// A sun of the study's captures (10:15, zenith ~40 degrees).
const SunPosition kSun{degrees_to_radians(40.0), degrees_to_radians(110.0)};

// The 81 directions of the Kider captures: 5 rings (1, 8, 16, 24, 32 samples).
std::vector<ViewDirection> measured_directions() {
  std::vector<ViewDirection> views;
  const double zenith_deg[] = {0.0, 18.0813, 36.6335, 56.2510, 77.8849};
  const int count[] = {1, 8, 16, 24, 32};
  for (int ring = 0; ring < 5; ++ring) {
    for (int k = 0; k < count[ring]; ++k) {
      views.push_back({degrees_to_radians(zenith_deg[ring]), 2.0 * kPi * k / count[ring]});
    }
  }
  return views;
}

std::shared_ptr<const SkyModel> nishita93_with(int resolution) {
  ModelConfig config;
  config.options["spheres"] = resolution;
  config.options["cylinders"] = resolution;
  PrecomputeContext context;
  context.threads = 1;
  return Nishita93Model::create(config, context);
}

std::shared_ptr<const SkyModel> oneal_with(int samples) {
  ModelConfig config;
  config.options["samples"] = samples;
  return ONealModel::create(config, {});
}

void radiance(benchmark::State& state, const SkyModel& model) {
  const auto sun = model.prepare_sun(kSun);
  const ViewDirection view{degrees_to_radians(56.251), degrees_to_radians(200.0)};
  SpectralBatch out;
  for (auto _ : state) {
    model.sky_radiance(*sun, {0.0}, std::span<const ViewDirection>(&view, 1), out);
    benchmark::DoNotOptimize(out.values.data());
  }
  state.SetItemsProcessed(state.iterations());
}

void batch(benchmark::State& state, const SkyModel& model) {
  const auto sun = model.prepare_sun(kSun);
  const std::vector<ViewDirection> views = measured_directions();
  SpectralBatch out;
  for (auto _ : state) {
    model.sky_radiance(*sun, {0.0}, views, out);
    benchmark::DoNotOptimize(out.values.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(views.size()));
}

void irradiance(benchmark::State& state, const SkyModel& model) {
  const auto sun = model.prepare_sun(kSun);
  for (auto _ : state) {
    const SpectralSample e = model.sky_irradiance(*sun, {0.0});
    benchmark::DoNotOptimize(e.value.data());
  }
}

void BM_Nishita93Radiance(benchmark::State& state) {
  radiance(state, *nishita93_with(static_cast<int>(state.range(0))));
}
void BM_Nishita93Batch81(benchmark::State& state) {
  batch(state, *nishita93_with(static_cast<int>(state.range(0))));
}
void BM_Nishita93SkyIrradiance(benchmark::State& state) {
  irradiance(state, *nishita93_with(static_cast<int>(state.range(0))));
}
void BM_Nishita93Precompute(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  PrecomputeContext context;
  context.threads = 1;
  for (auto _ : state) {
    const Nishita93Tables tables = Nishita93Tables::build({}, n, n, context);
    benchmark::DoNotOptimize(tables.sphere_count());
  }
}
void BM_ONealRadiance(benchmark::State& state) {
  radiance(state, *oneal_with(static_cast<int>(state.range(0))));
}
void BM_ONealBatch81(benchmark::State& state) {
  batch(state, *oneal_with(static_cast<int>(state.range(0))));
}
void BM_ONealSkyIrradiance(benchmark::State& state) {
  irradiance(state, *oneal_with(static_cast<int>(state.range(0))));
}

// Spheres = cylinders 16, 32, 64 (the paper's), 128; O'Neal samples 2 (O'Neil's), 4 (the
// paper's), 8, 32.
BENCHMARK(BM_Nishita93Radiance)->Arg(16)->Arg(32)->Arg(64)->Arg(128);
BENCHMARK(BM_Nishita93Batch81)->Arg(16)->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Nishita93SkyIrradiance)
    ->Arg(16)
    ->Arg(32)
    ->Arg(64)
    ->Arg(128)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Nishita93Precompute)
    ->Arg(16)
    ->Arg(32)
    ->Arg(64)
    ->Arg(128)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ONealRadiance)->Arg(2)->Arg(4)->Arg(8)->Arg(32);
BENCHMARK(BM_ONealBatch81)->Arg(2)->Arg(4)->Arg(8)->Arg(32)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ONealSkyIrradiance)->Arg(2)->Arg(4)->Arg(8)->Arg(32)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace clearsky
