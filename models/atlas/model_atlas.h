// The run-time-vs-error atlas of one model (docs/performance.md): every cost setting of
// atlas_settings.h built and timed (build wall and CPU time, table bytes, one per-sun
// preparation, one radiance, an 81-view batch, a sky irradiance), compared with the model's
// reference over the geometry set of atlas_geometry.h (relative spectral and luminance
// errors: median, 95th percentile, maximum) and, when captures are given, evaluated against
// them by evaluate_sky_model (models/evaluation/evaluate_model.h, the study's RMSE: the
// standard setting gives the RMSE of `clearsky evaluate`). The reference is checked against
// one step finer; the Pareto fronts and the draft setting (the cheapest with a 95th-percentile
// error of at most 2%) are named.
// One model is built at a time (the reference's samples are kept, its tables are not), so the
// peak memory is that of the largest setting. Thread-safety: reentrant; it builds its own models.
#pragma once

#include <functional>
#include <span>
#include <string>

#include "models/atlas/atlas_report.h"
#include "models/evaluation/evaluate_model.h"

namespace clearsky::atlas {

// The largest 95th-percentile spectral error of a draft setting.
inline constexpr double kDraftMaxP95Error = 0.02;

struct AtlasOptions {
  AtlasScope scope = AtlasScope::full;
  unsigned precompute_threads = 0;  // 0: all cores
  // Each query timing repeats the query for at least this long.
  double min_timing_s = 0.2;
  std::span<const MeasuredCapture> captures;  // prepared (capture_preparation.h); empty: no RMSE
  unsigned capture_threads = 1;
  // false: only the standard setting is evaluated against the captures (a model that
  // precomputes per sun, Haber, spends seconds on each capture's sun).
  bool rmse_of_every_setting = true;
  // One line per finished step ("bruneton standard: built in 17.2 s"); may be empty.
  std::function<void(const std::string&)> log;
};

ModelAtlasReport model_atlas(const ModelFactory& factory, const AtlasOptions& options);

}  // namespace clearsky::atlas
