// Run time of the two analytic models (measured in the models' READMEs, single thread): one
// 40-wavelength radiance after the per-sun preparation, a batch of the 81 evaluation directions,
// the sky irradiance (default quadrature, 24 x 48 directions), and the per-sun preparation itself.
// Hosek is measured both as the study evaluates it (one state per grid wavelength) and on its 11
// native bands interpolated (native_bands = 1).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "models/hosek/hosek.h"
#include "models/preetham/preetham.h"

namespace clearsky {
namespace {

const SunPosition kSun{degrees_to_radians(35.0), degrees_to_radians(120.0)};

std::shared_ptr<const SkyModel> make(const char* id, double native_bands = 0.0) {
  ModelConfig config;
  if (native_bands != 0.0) config.options["native_bands"] = native_bands;
  return std::string(id) == "preetham" ? preetham_factory().create(config, {})
                                       : hosek_factory().create(config, {});
}

// The study's 81 directions: a 9 x 9 grid of the unit square mapped to the disk
// (Shirley-Chiu), radius r -> zenith acos(1 - r^2).
std::vector<ViewDirection> evaluation_directions() {
  std::vector<ViewDirection> views;
  for (int i = 0; i < 9; ++i) {
    for (int j = 0; j < 9; ++j) {
      const double a = 2.0 * (i + 0.5) / 9.0 - 1.0, b = 2.0 * (j + 0.5) / 9.0 - 1.0;
      double r, phi;
      if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = (kPi / 4.0) * (b / a);
      } else {
        r = b;
        phi = (kPi / 2.0) - (kPi / 4.0) * (a / b);
      }
      views.push_back({std::acos(1.0 - r * r), phi});
    }
  }
  return views;
}

void radiance_one(benchmark::State& state, const char* id, double native_bands) {
  const auto model = make(id, native_bands);
  const auto sun = model->prepare_sun(kSun);
  const std::vector<ViewDirection> views = {{degrees_to_radians(50.0), degrees_to_radians(300.0)}};
  SpectralBatch out;
  for (auto _ : state) {
    model->sky_radiance(*sun, {}, views, out);
    benchmark::DoNotOptimize(out.values.data());
  }
}

void radiance_batch(benchmark::State& state, const char* id, double native_bands) {
  const auto model = make(id, native_bands);
  const auto sun = model->prepare_sun(kSun);
  const std::vector<ViewDirection> views = evaluation_directions();
  SpectralBatch out;
  for (auto _ : state) {
    model->sky_radiance(*sun, {}, views, out);
    benchmark::DoNotOptimize(out.values.data());
  }
  state.counters["per_view"] = benchmark::Counter(
      static_cast<double>(views.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void sky_irradiance(benchmark::State& state, const char* id, double native_bands) {
  const auto model = make(id, native_bands);
  const auto sun = model->prepare_sun(kSun);
  for (auto _ : state) {
    const SpectralSample e = model->sky_irradiance(*sun, {});
    benchmark::DoNotOptimize(e.value.data());
  }
}

void sun_irradiance(benchmark::State& state, const char* id) {
  const auto model = make(id);
  const auto sun = model->prepare_sun(kSun);
  for (auto _ : state) {
    const SpectralSample e = model->sun_irradiance(*sun, {});
    benchmark::DoNotOptimize(e.value.data());
  }
}

void prepare_sun(benchmark::State& state, const char* id, double native_bands) {
  const auto model = make(id, native_bands);
  for (auto _ : state) benchmark::DoNotOptimize(model->prepare_sun(kSun));
}

BENCHMARK_CAPTURE(radiance_one, preetham, "preetham", 0.0);
BENCHMARK_CAPTURE(radiance_one, hosek, "hosek", 0.0);
BENCHMARK_CAPTURE(radiance_one, hosek_native_bands, "hosek", 1.0);
BENCHMARK_CAPTURE(radiance_batch, preetham, "preetham", 0.0);
BENCHMARK_CAPTURE(radiance_batch, hosek, "hosek", 0.0);
BENCHMARK_CAPTURE(radiance_batch, hosek_native_bands, "hosek", 1.0);
BENCHMARK_CAPTURE(sky_irradiance, preetham, "preetham", 0.0);
BENCHMARK_CAPTURE(sky_irradiance, hosek, "hosek", 0.0);
BENCHMARK_CAPTURE(sky_irradiance, hosek_native_bands, "hosek", 1.0);
BENCHMARK_CAPTURE(sun_irradiance, preetham, "preetham");
BENCHMARK_CAPTURE(sun_irradiance, hosek, "hosek");
BENCHMARK_CAPTURE(prepare_sun, preetham, "preetham", 0.0);
BENCHMARK_CAPTURE(prepare_sun, hosek, "hosek", 0.0);
BENCHMARK_CAPTURE(prepare_sun, hosek_native_bands, "hosek", 1.0);

}  // namespace
}  // namespace clearsky
