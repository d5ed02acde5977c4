// The RGB skydome of GET /v1/skydome (api/skydome/skydome_render.h) per model and quality level:
// a latitude-longitude image of 1024 x 512 pixels (channels=rgb, half pixels, the sky and the
// albedo ground), written to a sink that drops the bytes. The model and its tables are built
// before the timing (a synchronous provider, no disk cache); the timing is the per-pixel work
// and the EXR encoding. The requirement's 4096 x 4096 request is a 4096 x 2048 latlong image:
// 16 times these pixels (docs/performance.md "RGB skydome"), which the benchmark does not run
// at full size because the slowest models take tens of seconds per iteration on the shared
// machine. The counter pixels_per_s is over the image's pixels.
// build/tests/clearsky_bench --benchmark_filter=RgbSkydome
#include <benchmark/benchmark.h>

#include <string>

#include "api/skydome/skydome_render.h"
#include "models/registry.h"
#include "tests/support/synchronous_provider.h"

namespace clearsky {
namespace {

constexpr int kWidth = 1024;

const clearsky::testing::SynchronousProvider& provider() {
  static const clearsky::testing::SynchronousProvider p(
      std::vector<ModelFactory>(registered_models().begin(), registered_models().end()));
  return p;
}

api::ApiRequest skydome_request(const std::string& model, const std::string& quality) {
  api::ApiRequest request;
  request.path = request.route = "/v1/skydome";
  request.query = {{"model", model},
                   {"sun_zenith", "40"},
                   {"sun_azimuth", "135"},
                   {"projection", "latlong"},
                   {"size", std::to_string(kWidth)},
                   {"channels", "rgb"},
                   {"ground", "albedo"},
                   {"quality", quality}};
  return request;
}

void rgb_skydome(benchmark::State& state, const std::string& model, const std::string& quality) {
  const api::ApiContext context{provider(), api::Limits{}};
  const api::SkydomeRender render = api::prepare_skydome(context, skydome_request(model, quality));
  std::size_t bytes = 0;
  const api::SkydomeRender::Sink sink = [&bytes](const char*, std::size_t size) {
    bytes += size;
    return true;
  };
  for (auto _ : state) {
    bytes = 0;
    if (!render.write(sink)) state.SkipWithError("the sink refused");
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["pixels_per_s"] = benchmark::Counter(
      static_cast<double>(render.width()) * render.height(), benchmark::Counter::kIsRate);
  state.counters["bytes"] = static_cast<double>(bytes);
}

const bool registered = [] {
  for (const char* quality : {"draft", "standard"}) {
    for (const ModelFactory& factory : registered_models()) {
      const std::string id = factory.descriptor->id;
      benchmark::RegisterBenchmark(("RgbSkydome/" + id + "/" + quality).c_str(), rgb_skydome, id,
                                   std::string(quality))
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(2);
    }
  }
  return true;
}();

}  // namespace
}  // namespace clearsky
