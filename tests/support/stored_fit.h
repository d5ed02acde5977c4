// A fit row written straight into the fits table (storage/repositories/fit_repository.h), for
// tests of what uses stored fits (docs/fits.md "Using a fit") without running a fit: its model,
// dataset, status and fitted values are what the test says.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "storage/repositories/fit_repository.h"
#include "storage/sqlite/database.h"

namespace clearsky::testing {

// Records a fit of model on the dataset with that id, and for status "succeeded" finishes it
// with values ({name, value} in the order of its free parameters); "failed" fails it; "running"
// and "queued" leave it so. Returns its id.
inline std::int64_t store_fit(storage::Database& db, std::int64_t dataset_id,
                              const std::string& model_id,
                              const std::vector<std::pair<std::string, double>>& values,
                              const std::string& status = "succeeded") {
  storage::NewFit fit;
  fit.dataset_id = dataset_id;
  fit.model_id = model_id;
  fit.model_version = "1";
  nlohmann::json free = nlohmann::json::array();
  nlohmann::json named = nlohmann::json::object();
  for (const auto& [name, value] : values) {
    free.push_back({{"name", name}, {"min", 0}, {"max", 10}, {"grid_points", 3}});
    named[name] = value;
  }
  fit.free_parameters = free.dump();
  fit.software_version = "test";
  fit.status = status == "queued" ? "queued" : "running";
  storage::FitRepository fits(db);
  const std::int64_t id = fits.start(fit);
  if (status == "succeeded") {
    storage::FitOutcome outcome;
    outcome.result = nlohmann::json{{"values", named}}.dump();
    fits.finish(id, outcome);
  } else if (status == "failed") {
    fits.fail(id, "test failure");
  }
  return id;
}

}  // namespace clearsky::testing
