// An evaluation run on a broadband irradiance dataset (broadband_evaluation_runner.h).
#include "api/evaluation/broadband_evaluation_runner.h"

#include <chrono>
#include <cmath>

#include "api/error/api_error.h"
#include "api/evaluation/broadband_model_altitude.h"
#include "api/evaluation/evaluation_fit.h"
#include "api/irradiance/broadband_irradiance.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/evaluation_run_repository.h"
#include "storage/repositories/irradiance_run_results.h"
#include "storage/repositories/irradiance_sample_repository.h"

namespace clearsky::api {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

std::vector<const ModelFactory*> broadband_models(const std::vector<std::string>& requested,
                                                  std::span<const ModelFactory> available) {
  const bool all = requested.empty() || (requested.size() == 1 && requested[0] == "all");
  std::vector<const ModelFactory*> factories;
  for (const ModelFactory* factory : resolve_models(requested, available)) {
    const auto unavailable = broadband_unavailable_reason(*factory->descriptor);
    if (!unavailable) {
      factories.push_back(factory);
    } else if (!all) {
      throw ApiError(422, "broadband_unavailable", "models",
                     "models: " + *unavailable +
                         "; a broadband irradiance dataset is evaluated "
                         "by the models with a broadband answer");
    }
  }
  return factories;
}

bool is_broadband_dataset(storage::Database& db, const std::string& dataset) {
  const auto found = storage::DatasetRepository(db).find(dataset);
  return found && found->kind == storage::kBroadbandIrradianceKind;
}

BroadbandEvaluationReport run_broadband_evaluation(storage::Database& db,
                                                   const EvaluationRequest& request,
                                                   std::span<const ModelFactory> available) {
  const std::vector<const ModelFactory*> factories = broadband_models(request.models, available);
  const auto dataset = storage::DatasetRepository(db).find(request.dataset);
  if (!dataset || dataset->kind != storage::kBroadbandIrradianceKind)
    throw std::invalid_argument("dataset '" + request.dataset +
                                "' is not a broadband irradiance dataset");
  const std::vector<storage::IrradianceSample> samples =
      storage::IrradianceSampleRepository(db).list(dataset->id);
  if (samples.empty())
    throw std::invalid_argument("dataset '" + request.dataset + "' has no irradiance samples");

  BroadbandEvaluationReport report;
  report.dataset = request.dataset;
  storage::EvaluationRunRepository runs(db);
  for (const ModelFactory* factory : factories) {
    const std::string& id = factory->descriptor->id;
    // A stored fit named by the parameters, expanded now: "latest" is the newest when the run
    // starts (evaluation_fit.h), as for captures.
    const nlohmann::json parameters =
        expand_evaluation_fit(db, request.parameters, *factory->descriptor);
    const ModelConfig config = config_for_model(*factory->descriptor, parameters);
    nlohmann::json applied = parameters_for_model(*factory->descriptor, parameters);
    if (parameters.contains(kFitParameter)) applied[kFitParameter] = parameters[kFitParameter];
    if (request.parameters.is_object() && request.parameters.contains(kQualityParameter))
      applied[kQualityParameter] = request.parameters[kQualityParameter];
    storage::NewRun run;
    run.dataset_id = dataset->id;
    run.job_id = request.job_id;
    run.model_id = id;
    run.model_version = factory->descriptor->version;
    run.parameters = applied.dump();
    run.configuration = config.canonical_string();
    run.software_version = request.software_version;
    run.min_wavelength_nm = kBroadbandMinNm;
    run.max_wavelength_nm = kBroadbandMaxNm;
    const std::int64_t run_id = runs.start(run);
    if (request.on_run_status) request.on_run_status(run_id, id, "running");
    try {
      const auto start = Clock::now();
      std::shared_ptr<const SkyModel> model;
      // The server's tables when it has them built; otherwise the run builds its own.
      if (request.provider != nullptr) model = provided_model(*request.provider, *factory, config);
      if (!model) model = factory->create(config, request.options.context);
      BroadbandModelRun result;
      result.run_id = run_id;
      result.model_id = id;
      result.precompute_seconds = seconds_since(start);
      const auto evaluate_start = Clock::now();
      const std::vector<ModelledIrradiance> modelled =
          modelled_broadband_irradiance(*model, samples);
      result.components = compare_broadband_irradiance(samples, modelled);
      result.rmse_w_m2 = pooled_rmse_w_m2(result.components);
      result.samples = static_cast<std::int64_t>(samples.size());
      for (const ModelledIrradiance& m : modelled)
        if (m.sun_zenith_deg < 90.0) ++result.samples_sun_up;
      result.evaluate_seconds = seconds_since(evaluate_start);
      std::vector<double> elevations_m;
      bool averaged = false;
      for (const storage::IrradianceSample& s : samples) {
        elevations_m.push_back(s.elevation_m);
        averaged = averaged || s.averaging_s.has_value();
      }
      const std::string steps =
          "broadband 300..4000 nm at each instant (sun from NREL SPA, no refraction)\n" +
          model_altitude_note(*factory->descriptor, elevations_m) + "\n" +
          (averaged ? "averaged samples: the model's mean over [time - averaging_s, time] "
                      "(Gauss-Legendre: the midpoint up to 60 s, 3 nodes per started hour)\n"
                    : "") +
          "compared with the sun above the horizon";
      // The components first: a run read as succeeded has them.
      std::vector<storage::IrradianceRunResult> stored;
      for (const BroadbandComponentResult& c : result.components)
        stored.push_back(
            {c.component, c.rmse_w_m2, c.mean_bias_w_m2, c.samples_compared, c.errors_w_m2});
      storage::IrradianceRunResultRepository(db).store(run_id, stored);
      runs.finish(run_id, result.rmse_w_m2.value_or(std::nan("")), result.precompute_seconds,
                  result.evaluate_seconds, steps, {});
      report.models.push_back(std::move(result));
    } catch (const std::exception& e) {
      runs.fail(run_id, e.what());
      if (request.on_run_status) request.on_run_status(run_id, id, "failed");
      throw;
    }
    if (request.on_run_status) request.on_run_status(run_id, id, "succeeded");
  }
  return report;
}

nlohmann::ordered_json broadband_evaluation_json(const BroadbandEvaluationReport& report,
                                                 bool with_errors) {
  const auto optional = [](const std::optional<double>& v) -> nlohmann::ordered_json {
    if (!v || !std::isfinite(*v)) return nullptr;
    return *v;
  };
  nlohmann::ordered_json models = nlohmann::ordered_json::array();
  for (const BroadbandModelRun& m : report.models) {
    nlohmann::ordered_json components = nlohmann::ordered_json::array();
    for (const BroadbandComponentResult& c : m.components) {
      nlohmann::ordered_json j{{"component", c.component},
                               {"rmse_w_m2", optional(c.rmse_w_m2)},
                               {"mean_bias_w_m2", optional(c.mean_bias_w_m2)},
                               {"samples_compared", c.samples_compared}};
      if (with_errors) {
        nlohmann::ordered_json errors = nlohmann::ordered_json::array();
        for (double e : c.errors_w_m2) errors.push_back(optional(e));
        j["errors_w_m2"] = std::move(errors);
      }
      components.push_back(std::move(j));
    }
    models.push_back({{"model", m.model_id},
                      {"run", m.run_id},
                      {"rmse_w_m2", optional(m.rmse_w_m2)},
                      {"samples", m.samples},
                      {"samples_sun_up", m.samples_sun_up},
                      {"components", std::move(components)},
                      {"precompute_seconds", m.precompute_seconds},
                      {"evaluate_seconds", m.evaluate_seconds}});
  }
  return {{"dataset", report.dataset}, {"models", std::move(models)}};
}

}  // namespace clearsky::api
