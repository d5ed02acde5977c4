// The stress run of one model (docs/stability.md): dense sweeps over its declared domain (sun
// zenith, view zenith through the horizon, view azimuth all round, altitude, every parameter
// its descriptor lists, wavelengths at the range edges), with the checks of stress_report.h.
// Each sweep varies one coordinate from the base point: sun zenith 30 degrees at azimuth 180,
// the lowest declared altitude, the model built with its default parameters (or the options
// given) on the wavelengths min_wavelength_nm, 550 nm and max_wavelength_nm of its descriptor.
// Thread-safety: stress_model is reentrant; it builds its own models.
#pragma once

#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "models/core/sky_model.h"
#include "models/stress/stress_report.h"

namespace clearsky::stress {

struct StressOptions {
  // At most this many points per sweep, evenly thinned from the full steps (0: every step).
  std::size_t max_points_per_sweep = 0;
  // Values of each parameter from its minimum to its maximum (one model built per value).
  std::size_t parameter_values = 7;
  // Whether the model's own options are swept (the atmosphere parameters always are); a quick
  // run may leave out the costly ones (table sizes, scattering orders).
  bool sweep_options = true;
  // Option values of the base configuration, applied where the descriptor lists the option
  // (e.g. smaller tables for a quick run); the others keep their defaults.
  std::map<std::string, double> options;
  // Threads of each precomputation (0: all cores).
  unsigned precompute_threads = 0;
  // Models that precompute per sun (Haber, Nishita96) sweep the sun zenith every 0.05 degree
  // over the whole range too, instead of only near the zenith, the horizon and the largest
  // zenith: one per-sun state per step, hours for Nishita96 (docs/stability.md).
  bool dense_per_sun_zeniths = false;
  // The sweeps to run, by name (sun_zenith, view_zenith, view_azimuth, altitude, parameters);
  // empty: all of them.
  std::set<std::string> sweeps;
};

// Relative difference of mirrored views above which the symmetry check fails: the contract's
// tolerance (docs/model-contract.md), float tables interpolating azimuths that differ by
// rounding only.
inline constexpr double kSymmetryTolerance = 1e-6;
// Slack of the energy bounds and the monotonic trends, relative: rounding, not physics.
inline constexpr double kBoundSlack = 1e-9;
// The horizon towards the sun brightens with aerosol (it scatters forwards) only while the
// slant optical depth of the view is thin: beyond, the light lost on the way outweighs the light
// scattered (docs/stability.md "Trends"). Checked at view zenith kTrendHorizonZenithDeg, where
// the slant depth is the vertical one over cos(85 degrees), and over the first
// kTrendRangeFraction of the parameter's range in kTrendValues values (fixed, so that the ratio
// between neighbours, which documented_limits.h bounds, means the same in every run).
inline constexpr double kThinSlantOpticalDepth = 1.0;
inline constexpr double kTrendHorizonZenithDeg = 85.0;
inline constexpr double kTrendRangeFraction = 0.05;
inline constexpr std::size_t kTrendValues = 5;
// The energy bound is checked for suns up to this zenith: the bound is that of a plane-parallel
// atmosphere, and within 5 degrees of the horizon a spherical one lights a horizontal plane from
// above the observer's horizon where E0 cos(sun zenith) goes to 0 (docs/stability.md "Energy
// bounds").
inline constexpr double kEnergyCheckMaxSunZenithDeg = 85.0;

ModelStressReport stress_model(const ModelFactory& factory, const StressOptions& options);

// No non-finite or negative value, no undeclared refusal, and no check failed beyond its
// documented limit (documented_limits.h).
bool stress_passed(const ModelStressReport& report);

}  // namespace clearsky::stress
