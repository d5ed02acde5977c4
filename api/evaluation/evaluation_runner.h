// An evaluation run as users start it (CLI `clearsky evaluate`, /v1/evaluations, scheduled
// jobs): models against a stored dataset, every run recorded in the database. The captures
// are loaded as stored and prepared as the paper did (capture_preparation.h: repair of the
// defective sample, SPA sun zenith, sun azimuth from the sky's symmetry); the preparation
// steps are stored with each run and the estimated azimuths with the captures.
// Parameters (docs/data-api.md "Evaluation parameters"): the request carries them as the user
// gave them; each model gets those its descriptor lists (atmosphere parameters and options
// alike) and nothing else, so that a parameter another requested model takes neither changes
// this model's configuration (its cache key, its tables) nor is recorded on its run.
// Samples a model cannot answer (models/evaluation/evaluate_model.h) are excluded or clamped as
// the evaluation parameter "out_of_domain" says ("exclude", the default, or "clamp"; stored
// with the run's parameters when given, docs/data-api.md "Samples a model cannot answer").
// Thread-safety: uses the given Database from the calling thread only.
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "api/service/model_provider.h"
#include "models/core/sky_model.h"
#include "models/evaluation/evaluate_model.h"
#include "models/quality/quality_levels.h"
#include "storage/repositories/compared_samples.h"
#include "storage/repositories/sample_errors_blob.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

struct EvaluationRequest {
  std::string dataset;
  std::vector<std::string> models;  // ids; {"all"} or empty: every registered model
  // Name -> value as the user gave it (a number, or "grass" for albedo); on the paper's
  // atmosphere and 40-bin grid. Checked by parse_evaluation_parameters (evaluations_api.h).
  nlohmann::json parameters = nlohmann::json::object();
  std::string software_version;
  std::optional<std::int64_t> job_id;
  EvaluationOptions options;
  // Where the models come from: the server's provider (its TableStore), so that an evaluation
  // or a job uses the tables and per-sun states the sky endpoints use and builds only what is
  // not built yet (waiting while a build is under way); null (the CLI, tests): each run builds
  // its model (ModelFactory::create). A configuration the provider refuses for another reason
  // (its table memory budget) is built by the run itself, as without a provider.
  const ModelProvider* provider = nullptr;
  // Told each model's run status as it changes: "running" when the run is recorded (before it
  // is computed), then "succeeded" or "failed".
  std::function<void(std::int64_t run_id, const std::string& model_id, const std::string& status)>
      on_run_status;
};

struct ModelRun {
  std::int64_t run_id = 0;
  EvaluationResult result;
};

struct EvaluationReport {
  std::string dataset;
  double min_wavelength_nm = 360;
  double max_wavelength_nm = 720;
  OutOfDomain out_of_domain = OutOfDomain::exclude;
  std::vector<ModelRun> models;  // in the order requested
};

// A capture's per-sample errors as they are stored with the run (sample_errors_blob.h): what
// both the CLI's JSON and the API's answer are made of, so that the two agree to the bit;
// wavelength_count: the run's compared wavelengths (EvaluationResult::wavelengths_nm).
storage::SampleErrorTable stored_sample_errors(const CaptureEvaluation& capture,
                                               std::size_t wavelength_count);
// A capture's excluded and clamped samples as they are stored with the run.
std::vector<storage::SampleHandling> stored_sample_handling(const CaptureEvaluation& capture);

// The name of the evaluation parameter that chooses what is done with the samples a model
// cannot answer; it applies to every model and is no model's parameter.
inline constexpr const char* kOutOfDomainParameter = "out_of_domain";
// The handling the parameters choose (exclude when not given); throws std::invalid_argument
// naming out_of_domain for a value that is not "exclude" or "clamp".
OutOfDomain out_of_domain_of(const nlohmann::json& parameters);

// The name of the evaluation parameter that chooses each model's quality level (draft, standard,
// reference; docs/quality-levels.md): it applies to every model, whose explicit options win.
inline constexpr const char* kQualityParameter = "quality";
// The level the parameters choose (standard when not given); throws std::invalid_argument naming
// quality for another value.
QualityLevel quality_of(const nlohmann::json& parameters);

// The parameters among `parameters` that the model's descriptor lists (the others dropped).
nlohmann::json parameters_for_model(const ModelDescriptor& descriptor,
                                    const nlohmann::json& parameters);
// The model's configuration: the defaults with the parameters its descriptor lists applied
// (unchecked: validate_config checks it). Throws std::invalid_argument naming a parameter
// whose value is neither a number nor, for albedo, "grass".
ModelConfig config_for_model(const ModelDescriptor& descriptor, const nlohmann::json& parameters);

// The factories named by a --models value: "all" (every one of `available`) or ids; throws
// std::invalid_argument naming unknown ids (before anything is computed).
std::vector<const ModelFactory*> resolve_models(const std::vector<std::string>& requested,
                                                std::span<const ModelFactory> available);

// The model of `config` from the provider, waiting while its tables are being built (503
// model_not_ready); null when the provider refuses it for another reason (a configuration the
// descriptor rejects, the table memory budget, a failed build).
std::shared_ptr<const SkyModel> provided_model(const ModelProvider& provider,
                                               const ModelFactory& factory,
                                               const ModelConfig& config);

// Runs and stores the evaluation of models among `available` (default: the registered
// models). Throws std::invalid_argument for an unknown dataset or model or an empty dataset;
// a model failing is recorded as a failed run, then rethrown.
EvaluationReport run_evaluation(storage::Database& db, const EvaluationRequest& request);
EvaluationReport run_evaluation(storage::Database& db, const EvaluationRequest& request,
                                std::span<const ModelFactory> available);

}  // namespace clearsky::api
