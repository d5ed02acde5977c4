// Time per NREL SPA evaluation: one solar_position call (the position at one instant) and one
// sun_times call (sunrise/transit/sunset: four geocentric evaluations and the interpolation).
#include <benchmark/benchmark.h>

#include "models/solar/solar_position.h"

namespace {

clearsky::SolarPositionInput golden_example() {
  clearsky::SolarPositionInput in;
  in.unix_time_utc_s = 1066419030.0;  // 2003-10-17T12:30:30-07:00
  in.latitude_deg = 39.742476;
  in.longitude_deg = -105.1786;
  in.elevation_m = 1830.14;
  in.pressure_mbar = 820.0;
  in.temperature_c = 11.0;
  in.delta_t_s = 67.0;
  return in;
}

void BM_SolarPosition(benchmark::State& state) {
  clearsky::SolarPositionInput in = golden_example();
  for (auto _ : state) {
    in.unix_time_utc_s += 1.0;  // a new instant each call, so nothing is hoisted
    benchmark::DoNotOptimize(clearsky::solar_position(in));
  }
}
BENCHMARK(BM_SolarPosition);

void BM_SunTimes(benchmark::State& state) {
  clearsky::SolarPositionInput in = golden_example();
  for (auto _ : state) {
    in.unix_time_utc_s += 60.0;
    benchmark::DoNotOptimize(clearsky::sun_times(in, -7.0));
  }
}
BENCHMARK(BM_SunTimes);

}  // namespace
