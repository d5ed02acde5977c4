// Speed of the per-sun models (Haber, Nishita96): the per-sun precomputation at the paper's
// resolution and at cheaper settings (their RMSE on the 15 captures is in the models'
// READMEs), one 40-wavelength radiance, a batch of the 81 measured directions, and the sky
// irradiance at the ground (SkyModel's 24 x 48 quadrature). Precomputations use all cores
// (the targets are per sun angle on 2 cores: Haber < 5 s, Nishita96 < 0.1 s and
// 30 MB); queries run on one thread (Nishita96 < 30 us per radiance, < 50 ms per sky
// irradiance). Each precomputation iteration uses a new model so that its cache is cold.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "models/haber/haber.h"
#include "models/nishita96/nishita96.h"

namespace clearsky {
namespace {

const SunPosition kSun{degrees_to_radians(40.0), degrees_to_radians(110.0)};

std::vector<ViewDirection> measured_directions() {
  std::vector<ViewDirection> views;
  const double zenith_deg[] = {0.0, 18.0813, 36.6335, 56.2510, 77.8849};
  const int count[] = {1, 8, 16, 24, 32};
  for (int ring = 0; ring < 5; ++ring) {
    for (int k = 0; k < count[ring]; ++k)
      views.push_back({degrees_to_radians(zenith_deg[ring]), 2.0 * kPi * k / count[ring]});
  }
  return views;
}

ModelConfig haber_config(int sectors, int stride) {
  ModelConfig config;
  config.options["azimuth_sectors"] = sectors;
  config.options["shell_stride"] = stride;
  return config;
}

void BM_HaberPerSun(benchmark::State& state) {
  const ModelConfig config =
      haber_config(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  for (auto _ : state) {
    const auto model = haber::HaberModel::create(config);
    benchmark::DoNotOptimize(model->prepare_sun(kSun));
  }
}
BENCHMARK(BM_HaberPerSun)
    ->Args({72, 4})
    ->Args({72, 8})
    ->Args({48, 4})
    ->Args({36, 4})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

void BM_Nishita96PerSun(benchmark::State& state) {
  ModelConfig config;
  config.options["table_nodes"] = static_cast<double>(state.range(0));
  const auto model = nishita96_factory().create(config, {});
  double bytes = 0.0;
  int i = 0;
  for (auto _ : state) {
    // A new sun every iteration: every build misses the cache.
    const auto sun_state =
        model->prepare_sun({degrees_to_radians(20.0 + 0.01 * i++), kSun.azimuth_rad});
    bytes = static_cast<double>(sun_state->memory_bytes());
  }
  state.counters["MB"] = bytes / 1e6;
}
BENCHMARK(BM_Nishita96PerSun)->Arg(33)->Arg(17)->Unit(benchmark::kMillisecond)->UseRealTime();

// The per-sun build at the paper's 33 nodes with the sun's and anti-sun's directions near the
// horizontal (argument: sun zenith, degrees): 89 builds their grazing layouts (4 times finer
// across, nishita96_tables.h), 80 both layouts of each (the blend band).
void BM_Nishita96PerSunNearHorizon(benchmark::State& state) {
  ModelConfig config;
  config.options["table_nodes"] = 33;
  const auto model = nishita96_factory().create(config, {});
  double bytes = 0.0;
  int i = 0;
  for (auto _ : state) {
    const auto sun_state = model->prepare_sun(
        {degrees_to_radians(static_cast<double>(state.range(0)) + 0.01 * i++), kSun.azimuth_rad});
    bytes = static_cast<double>(sun_state->memory_bytes());
  }
  state.counters["MB"] = bytes / 1e6;
}
BENCHMARK(BM_Nishita96PerSunNearHorizon)
    ->Arg(80)
    ->Arg(89)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

template <class Make>
void radiance_benchmarks(benchmark::State& state, Make make, int mode) {
  const auto model = make();
  const auto sun_state = model->prepare_sun(kSun);
  const auto views =
      mode == 0 ? std::vector<ViewDirection>{{degrees_to_radians(45.0), degrees_to_radians(200.0)}}
                : measured_directions();
  SpectralBatch out;
  for (auto _ : state) {
    if (mode == 2) {
      benchmark::DoNotOptimize(model->sky_irradiance(*sun_state, Viewpoint{}));
    } else {
      model->sky_radiance(*sun_state, Viewpoint{}, views, out);
      benchmark::DoNotOptimize(out.values.data());
    }
  }
}

void BM_HaberQuery(benchmark::State& state) {
  radiance_benchmarks(
      state, [] { return haber::HaberModel::create(ModelConfig{}); },
      static_cast<int>(state.range(0)));
}
// 0: one radiance, 1: the 81 directions, 2: sky irradiance.
BENCHMARK(BM_HaberQuery)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

void BM_Nishita96Query(benchmark::State& state) {
  radiance_benchmarks(
      state, [] { return nishita96_factory().create(ModelConfig{}, {}); },
      static_cast<int>(state.range(0)));
}
BENCHMARK(BM_Nishita96Query)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace clearsky
