// An atmosphere fit as users start it (CLI `clearsky fit`, POST /v1/fits; docs/fits.md): a model
// fitted to a stored dataset (prepared as evaluations prepare it, api/evaluation/
// prepared_dataset.h) by models/fitting/atmosphere_fit.h, every fit recorded in the database
// (storage/repositories/fit_repository.h) before it is computed, with its progress while it
// runs and its results when it ends.
// Request members (checked by check_fit_request before anything is computed; InvalidInput
// naming the member): model; free (names; empty: alpha, beta, g for the Bruneton family, else
// turbidity); bounds ({name: [min, max]}); grid (one count per free parameter); captures
// (labels; empty: all); parameters (fixed parameters and options, as the evaluation's
// "parameters", docs/data-api.md "Evaluation parameters", "out_of_domain" included; a free
// parameter given there is the start); search_options (the search's table options; absent:
// the cheap tables of fit_space.h); per_capture; cross_validate; the refinement budgets.
// Thread-safety: uses the given Database from the calling thread only.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "models/fitting/atmosphere_fit.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

struct FitRequest {
  std::string dataset;
  std::string model;
  std::vector<std::string> free;
  nlohmann::json bounds = nlohmann::json::object();
  std::vector<int> grid;
  std::vector<std::string> captures;
  nlohmann::json parameters = nlohmann::json::object();
  std::optional<nlohmann::json> search_options;
  bool per_capture = false;
  bool cross_validate = false;
  int max_refine_evaluations = 200;
  int max_fold_refine_evaluations = 60;
  std::string software_version;
  unsigned capture_threads = 0;  // EvaluationOptions::capture_threads
  std::function<void(double fraction, std::string_view stage)> progress;
  const std::atomic<bool>* cancel = nullptr;
};

// The request checked and turned into the fit's settings (no dataset access).
struct CheckedFit {
  const ModelFactory* factory = nullptr;
  FitSettings settings;
  nlohmann::json fixed_parameters;  // as applied to the model
};
CheckedFit check_fit_request(const FitRequest& request);

// Records the fit (running), runs it on the dataset's captures and records the outcome; a failure
// is recorded as failed and rethrown. Throws std::invalid_argument for an unknown dataset or
// capture label, InvalidInput for a bad request. Returns the fit's id. queued_id: a fit already
// recorded queued (POST /v1/fits), run instead of recording a new one.
std::int64_t run_fit(storage::Database& db, const FitRequest& request,
                     std::optional<std::int64_t> queued_id = std::nullopt);

// Records a queued fit of a checked request (the HTTP path, before it is queued); returns its id.
std::int64_t record_queued_fit(storage::Database& db, const FitRequest& request);

}  // namespace clearsky::api
