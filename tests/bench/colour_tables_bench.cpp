// The tables a draft colour request builds (api/colour/colour_wavelengths.h): each table model
// (Bruneton, Elek, measured_aerosols) at the draft level's options, on the paper's 40
// wavelengths (what an RGB request built before) against the draft colour grid's 9 points. One
// build per iteration, no disk cache; the counter table_bytes is the built model's tables.
// build/tests/clearsky_bench --benchmark_filter=ColourTables
#include <benchmark/benchmark.h>

#include <string>

#include "api/colour/colour_wavelengths.h"
#include "models/registry.h"

namespace clearsky {
namespace {

void colour_tables(benchmark::State& state, const std::string& model, bool colour_grid) {
  const ModelFactory& factory = *find_model(model);
  ModelConfig config;
  apply_quality_level(*factory.descriptor, quality_setting(model, QualityLevel::draft),
                      config.options);
  if (colour_grid) config.wavelengths = WavelengthGrid::points(api::kDraftColourWavelengthsNm);
  std::size_t bytes = 0;
  for (auto _ : state) {
    const auto built = factory.create(config, {});
    bytes = built->table_bytes();
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["table_bytes"] = static_cast<double>(bytes);
  state.counters["wavelengths"] = static_cast<double>(config.wavelengths.size());
}

const bool registered = [] {
  for (const char* model : {"bruneton", "elek", "measured_aerosols"}) {
    for (bool colour_grid : {false, true}) {
      benchmark::RegisterBenchmark(
          ("ColourTables/" + std::string(model) + (colour_grid ? "/draft_colour_9" : "/draft_40"))
              .c_str(),
          colour_tables, std::string(model), colour_grid)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(1);
    }
  }
  return true;
}();

}  // namespace
}  // namespace clearsky
