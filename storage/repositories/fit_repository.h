// Atmosphere fits as rows of the fits table (schema version 7, docs/fits.md "Stored fits"): a
// fit is recorded `running` (or `queued` for one that waits for a worker) before it is computed,
// its progress and stage updated while it runs, then finished (`succeeded` with its results) or
// failed; start-up turns what a crash left queued or running into `interrupted`. The parameters,
// captures and results are JSON text that the api layer writes and reads (api/fits/).
// SQL on this table lives only here. Ids are never reused (AUTOINCREMENT).
// Thread-safety: as the Database it uses.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "storage/sqlite/database.h"

namespace clearsky::storage {

struct NewFit {
  std::int64_t dataset_id = 0;
  std::string model_id;
  std::string model_version;
  std::string free_parameters = "[]";   // JSON: [{name, min, max, grid_points}]
  std::string fixed_parameters = "{}";  // JSON: as the evaluation's "parameters"
  std::string search_options = "{}";    // JSON: name -> value
  std::string captures = "[]";          // JSON: the labels fitted
  std::string settings = "{}";          // JSON: per_capture, cross_validate, budgets
  std::string software_version;
  std::string status = "running";  // or "queued"
};

struct FitOutcome {
  // JSON: {"values": {name: value}, "grid": {"values", "rmse", "evaluations"}, "refine":
  // {"algorithm", "stop", "evaluations"}, "search_setting_differs"}
  std::string result = "{}";
  double rmse_before = 0;
  double rmse_search = 0;
  double rmse_after = 0;
  std::optional<double> cross_validated_rmse;
  std::string per_capture = "[]";  // JSON
  std::string uncertainty = "[]";  // JSON
  std::string history = "[]";      // JSON
  std::string timings = "{}";      // JSON: stage -> s
};

struct FitRecord {
  std::int64_t id = 0;
  std::string dataset;  // the dataset's name
  NewFit fit;
  double progress = 0;
  std::optional<std::string> stage;
  std::optional<FitOutcome> outcome;  // when succeeded
  std::optional<std::string> error;
  std::string created_utc;
  std::optional<std::string> finished_utc;
};

class FitRepository {
 public:
  explicit FitRepository(Database& db) : db_(db) {}
  std::int64_t start(const NewFit& fit);
  // queued -> running.
  void run(std::int64_t id);
  void progress(std::int64_t id, double fraction, const std::string& stage);
  void finish(std::int64_t id, const FitOutcome& outcome);
  void fail(std::int64_t id, const std::string& error, const std::string& status = "failed");
  // Every fit still queued or running becomes interrupted with error; returns how many.
  int interrupt_unfinished(const std::string& error);
  std::optional<FitRecord> get(std::int64_t id);
  // Newest first: at most limit fits with id < before_id (0: from the newest).
  std::vector<FitRecord> list(int limit, std::int64_t before_id = 0);
  // The newest (highest id) succeeded fit of the model, on the dataset when given (fit=latest,
  // docs/fits.md "Using a fit"); nullopt when there is none.
  std::optional<FitRecord> latest_succeeded(const std::string& model_id,
                                            std::optional<std::int64_t> dataset_id);

 private:
  Database& db_;
};

}  // namespace clearsky::storage
