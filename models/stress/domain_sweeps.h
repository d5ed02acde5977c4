// The coordinates a stress run sweeps through a model's declared domain (docs/stability.md):
// sun zeniths in 0.05-degree steps, view zeniths in 0.05-degree steps with 0.005-degree steps
// within 2 degrees of the horizon, view azimuths all round in 0.05-degree steps, altitudes on a
// log scale (0.01 decade) from 1 m to 100 km and on to the largest declared altitude (every 20 m
// within 2 km of the top of the atmosphere), and the
// values of a model parameter from its minimum to its maximum. Degrees and metres, as named.
#pragma once

#include <cstddef>
#include <vector>

#include "models/core/model_descriptor.h"

namespace clearsky::stress {

inline constexpr double kSunZenithStepDeg = 0.05;
inline constexpr double kViewZenithStepDeg = 0.05;
inline constexpr double kViewZenithNearHorizonStepDeg = 0.005;
inline constexpr double kNearHorizonHalfWidthDeg = 2.0;
inline constexpr double kViewAzimuthStepDeg = 0.05;
inline constexpr double kAltitudeStepDecades = 0.01;
inline constexpr double kAltitudeSweepTopM = 100e3;
inline constexpr double kNearTopHalfWidthM = 2000.0;
inline constexpr double kNearTopStepM = 20.0;

// first, first + step, ..., up to last (included, within rounding).
std::vector<double> steps_from_to(double first, double last, double step);
// At most max_points of the values, evenly spread, both ends kept (0: all of them).
std::vector<double> thinned(const std::vector<double>& values, std::size_t max_points);

// 0 to max_sun_zenith_deg.
std::vector<double> sun_zeniths_deg(double max_sun_zenith_deg);
// For models that precompute per sun (seconds each): 0.05-degree steps within 1 degree of the
// zenith, of the horizon and of max_sun_zenith_deg, 5-degree steps between.
std::vector<double> sparse_sun_zeniths_deg(double max_sun_zenith_deg);
inline constexpr double kSparseSunZenithStepDeg = 5.0;
// The sun zeniths of the sun sweep: every step, or the sparse list for a model that precomputes
// per sun unless dense_per_sun (StressOptions::dense_per_sun_zeniths) asks for every step.
std::vector<double> swept_sun_zeniths_deg(double max_sun_zenith_deg, bool per_sun_precomputation,
                                          bool dense_per_sun);
// 0 to last_deg, finer within kNearHorizonHalfWidthDeg of 90.
std::vector<double> view_zeniths_deg(double last_deg);
// [0, 360): offsets from the sun's azimuth.
std::vector<double> azimuth_offsets_deg();
// 0, then 1 m to 100 km on a log scale, then on to max_altitude_m when it is higher; and
// within 2 km of the top of the atmosphere (top_altitude_m) every 20 m.
std::vector<double> altitudes_m(double max_altitude_m, double top_altitude_m);
// count values of a parameter from its minimum to highest (its maximum, or less for a costly
// resolution; see parameter_sweep_top), integers rounded and repeated values dropped.
std::vector<double> parameter_values(const ParameterSpec& parameter, double highest,
                                     std::size_t count);
// The largest value of a parameter a stress run builds: its maximum, except for integer
// options above 1 (resolutions and sample counts), swept up to twice their base value because a
// build at the maximum costs hours (Bruneton's 128 x 512 x 128 x 64 tables); docs/stability.md.
double parameter_sweep_top(const ParameterSpec& parameter, double base_value);

}  // namespace clearsky::stress
