// JSON form of the run-time-vs-error atlas (`clearsky atlas --json`, docs/performance.md): one
// object per model with its geometry set, reference (how chosen, and its check against one step
// finer), settings (options, grid, build and query times, table bytes, errors against the
// reference, RMSE against the dataset), Pareto fronts and draft setting. Times in seconds,
// errors relative, RMSE in mW/(m2.sr.nm); a number that is not finite is written as null.
#pragma once

#include <nlohmann/json.hpp>

#include "models/atlas/atlas_report.h"

namespace clearsky::api {

nlohmann::json atlas_report_to_json(const atlas::ModelAtlasReport& report);

}  // namespace clearsky::api
