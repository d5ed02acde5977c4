// A stored dataset's captures prepared as the paper did (models/evaluation/
// capture_preparation.h: repair of the defective sample, SPA sun zenith, sun azimuth from the
// sky's symmetry), for everything that compares models with it: evaluation runs
// (evaluation_runner.h) and fits (api/fits/fit_runner.h). The estimated azimuths are stored
// with the captures; the estimate is deterministic, so it is recomputed rather than trusted from
// an earlier run.
// Thread-safety: uses the given Database from the calling thread only.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "models/evaluation/measured_sky.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

struct PreparedDataset {
  std::int64_t dataset_id = 0;
  std::vector<std::int64_t> capture_ids;  // in the order of captures
  std::vector<MeasuredCapture> captures;  // stored order, prepared
  std::string processing_steps;           // "label: step" lines, as stored with runs
};

// Throws std::invalid_argument for an unknown dataset or one without captures.
PreparedDataset load_prepared_dataset(storage::Database& db, const std::string& dataset);

}  // namespace clearsky::api
