// What the run-time-vs-error atlas measures per model and setting (docs/performance.md).
// Times in seconds; errors relative (0.01 = 1%); RMSE in mW/(m2.sr.nm).
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "models/atlas/atlas_settings.h"

namespace clearsky::atlas {

// Median, 95th percentile and maximum of a set of relative errors, over `count` samples.
struct ErrorSummary {
  double median = 0;
  double p95 = 0;
  double max = 0;
  std::size_t count = 0;
};

struct SettingMeasurement {
  AtlasSetting setting;
  std::string role;  // "setting", "reference" or "reference_check"
  std::size_t wavelengths = 0;
  double build_wall_s = 0;
  double build_cpu_s = 0;                 // the process's CPU time over the build (all its threads)
  std::size_t table_bytes = 0;            // the built model's table_bytes()
  std::size_t estimated_table_bytes = 0;  // the factory's estimate (0: none)
  double sun_state_wall_s = 0;            // one per-sun preparation (per-sun models), else 0
  double radiance_s = 0;                  // one view (on the setting's grid)
  double batch_81_s = 0;                  // 81 views
  double sky_irradiance_s = 0;            // one horizontal sky irradiance
  // Against the reference over the geometry set: the spectrum's relative L2 difference on the
  // 40 bins the reference answers, and the luminance's relative difference.
  ErrorSummary spectral_error;
  ErrorSummary luminance_error;
  std::size_t samples_refused = 0;  // answered by the reference, refused by the setting
  std::optional<double> rmse;       // against the dataset, when one was given
  std::size_t rmse_wavelengths = 0;
  double evaluate_s = 0;
  // The cost the draft level is chosen by: build CPU + one sun preparation + one 81-view batch.
  double first_sky_s() const { return build_cpu_s + sun_state_wall_s + batch_81_s; }
};

struct ModelAtlasReport {
  std::string model;
  std::string version;
  std::string reference_reason;
  std::vector<double> sun_zeniths_deg;
  std::vector<double> altitudes_m;
  std::size_t views = 0;
  std::vector<SettingMeasurement> settings;           // settings[0]: standard
  SettingMeasurement reference;                       // its errors are zero by definition
  std::optional<SettingMeasurement> reference_check;  // errors: the reference against it
  // Names of the settings on the Pareto front of p95 spectral error against build CPU time
  // (plus one sun preparation) and against the 81-view batch time.
  std::vector<std::string> pareto_build;
  std::vector<std::string> pareto_query;
  // The cheapest setting (first_sky_s) whose p95 spectral error is at most 2%; empty: none.
  std::string draft;
  double seconds = 0;
};

}  // namespace clearsky::atlas
