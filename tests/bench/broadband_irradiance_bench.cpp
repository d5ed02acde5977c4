// The cost of the broadband step (api/irradiance/broadband_plane_irradiance.h), what
// GET /v1/irradiance adds to a model's spectral answer and GET /v1/irradiance/series adds to
// every daytime step, on the paper's 40 bins with the sun 40 degrees from the zenith:
//  - BM_BroadbandExtensionOneSun: the per-sun integration (the absorbers' mean transmittance
//    over each model bin, SPCTRAL2's direct and diffuse on 1 nm steps outside the model's
//    range), the bulk of it;
//  - BM_BroadbandPlaneIrradiance: one /v1/irradiance's whole broadband step, the sun's
//    integration then the direct normal, the horizontal and one tilted plane;
//  - BM_BroadbandPlaneGivenTheSun: each further plane of the same sun (a series' planes).
// Compare with the model's own sky irradiance on a tilted plane (24 x 48 radiance queries,
// about 0.2 ms for Bruneton on an idle core: models/bruneton/README.md).
#include <benchmark/benchmark.h>

#include <numeric>

#include "api/irradiance/broadband_plane_irradiance.h"
#include "models/core/numeric.h"

namespace clearsky {
namespace {

// Spectra of the magnitude of a clear noon sky on the paper's grid (W/(m2.nm)).
struct PaperGridSun {
  WavelengthGrid grid = WavelengthGrid::paper_bins();
  std::vector<std::size_t> indices = std::vector<std::size_t>(grid.size());
  api::HorizontalIrradiance horizontal;
  api::PlaneIrradiance plane;
  api::BroadbandConditions conditions;

  PaperGridSun() {
    std::iota(indices.begin(), indices.end(), std::size_t{0});
    const std::size_t n = grid.size();
    conditions.sun_zenith_rad = degrees_to_radians(40.0);
    horizontal.with_direct = horizontal.with_sky = true;
    horizontal.beam_factor = std::cos(conditions.sun_zenith_rad);
    horizontal.direct_normal = Spectrum(n, 1.2);
    horizontal.direct = Spectrum(n, 1.2 * horizontal.beam_factor);
    horizontal.diffuse = Spectrum(n, 0.2);
    horizontal.global = horizontal.direct + horizontal.diffuse;
    plane.with_sky = plane.with_ground = true;
    plane.beam_factor = 0.95;
    plane.direct = Spectrum(n, 1.2 * plane.beam_factor);
    plane.sky_diffuse = Spectrum(n, 0.15);
    plane.ground_diffuse = Spectrum(n, 0.01);
    plane.global = plane.direct + plane.sky_diffuse + plane.ground_diffuse;
  }
};

void BM_BroadbandExtensionOneSun(benchmark::State& state) {
  const PaperGridSun s;
  for (auto _ : state) {
    const api::BroadbandExtension extension(s.grid, s.indices, s.conditions);
    benchmark::DoNotOptimize(extension.direct_normal_w_m2(s.horizontal.direct_normal));
  }
}
BENCHMARK(BM_BroadbandExtensionOneSun)->Unit(benchmark::kMicrosecond);

void BM_BroadbandPlaneIrradiance(benchmark::State& state) {
  const PaperGridSun s;
  for (auto _ : state) {
    const api::BroadbandExtension extension(s.grid, s.indices, s.conditions);
    const api::BroadbandHorizontalIrradiance h =
        api::broadband_horizontal_irradiance(extension, s.horizontal);
    benchmark::DoNotOptimize(api::broadband_plane_irradiance(extension, s.horizontal, h, s.plane));
  }
}
BENCHMARK(BM_BroadbandPlaneIrradiance)->Unit(benchmark::kMicrosecond);

void BM_BroadbandPlaneGivenTheSun(benchmark::State& state) {
  const PaperGridSun s;
  const api::BroadbandExtension extension(s.grid, s.indices, s.conditions);
  const api::BroadbandHorizontalIrradiance h =
      api::broadband_horizontal_irradiance(extension, s.horizontal);
  for (auto _ : state)
    benchmark::DoNotOptimize(api::broadband_plane_irradiance(extension, s.horizontal, h, s.plane));
}
BENCHMARK(BM_BroadbandPlaneGivenTheSun)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace clearsky
