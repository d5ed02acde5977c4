// A stored dataset of captures a model made with known parameters (tests/models/fitting/
// model_made_sky.h), for tests of fits through the database and the HTTP API (docs/fits.md):
// each capture keeps the sun position it was made for, as evaluations read it
// (api/evaluation/prepared_dataset.h), so that a fit of that model finds the parameters back.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "models/registry.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/sqlite/database.h"
#include "tests/models/fitting/model_made_sky.h"

namespace clearsky::testing {

// Stores in dataset `name` one capture per (sun zenith, sun azimuth) in degrees, made by the
// model `model_id` with config, labelled "made 0", "made 1", ...; returns the dataset's id.
inline std::int64_t store_model_made_dataset(
    storage::Database& db, const std::string& name, const std::string& model_id,
    const ModelConfig& config, const std::vector<std::pair<double, double>>& suns_deg) {
  const ModelFactory* factory = find_model(model_id);
  if (factory == nullptr) throw std::logic_error("no model " + model_id);
  const std::shared_ptr<const SkyModel> model = factory->create(config, {});
  const std::int64_t dataset = storage::DatasetRepository(db).find_or_create(name, "kider2014");
  storage::Transaction transaction(db);
  for (std::size_t i = 0; i < suns_deg.size(); ++i) {
    MeasuredCapture capture = model_made_capture(*model, suns_deg[i].first, suns_deg[i].second);
    capture.label = "made " + std::to_string(i);
    capture.unix_time_utc_s += 900.0 * static_cast<double>(i);
    storage::CaptureRepository(db).insert(dataset, capture, "made" + std::to_string(i), "test");
  }
  transaction.commit();
  return dataset;
}

}  // namespace clearsky::testing
