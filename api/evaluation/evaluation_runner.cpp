// Stored evaluation runs (evaluation_runner.h).
#include "api/evaluation/evaluation_runner.h"

#include <chrono>
#include <stdexcept>
#include <thread>

#include "api/error/api_error.h"
#include "api/evaluation/evaluation_fit.h"
#include "api/evaluation/prepared_dataset.h"
#include "api/request/sky_request.h"
#include "models/core/fit_domain.h"
#include "models/core/invalid_input.h"
#include "models/registry.h"
#include "storage/repositories/evaluation_run_repository.h"

namespace clearsky::api {

storage::SampleErrorTable stored_sample_errors(const CaptureEvaluation& capture,
                                               std::size_t wavelength_count) {
  storage::SampleErrorTable table;
  const std::size_t n = capture.samples.size();
  table.wavelength_count = static_cast<std::uint32_t>(wavelength_count);
  table.samples.reserve(n);
  for (const SampleEvaluation& s : capture.samples)
    table.samples.push_back({s.index, static_cast<float>(s.view_zenith_deg),
                             static_cast<float>(s.view_azimuth_deg), s.rmse, s.bias});
  table.errors.assign(capture.sample_errors.begin(), capture.sample_errors.end());
  return table;
}

std::vector<storage::SampleHandling> stored_sample_handling(const CaptureEvaluation& capture) {
  std::vector<storage::SampleHandling> out;
  const auto add = [&](const std::vector<OutOfDomainSamples>& lists, const char* handling) {
    for (const OutOfDomainSamples& l : lists)
      out.push_back({handling, std::string(to_string(l.reason)),
                     std::vector<std::int32_t>(l.indices.begin(), l.indices.end())});
  };
  add(capture.excluded, "excluded");
  add(capture.clamped, "clamped");
  return out;
}

OutOfDomain out_of_domain_of(const nlohmann::json& parameters) {
  if (!parameters.is_object() || !parameters.contains(kOutOfDomainParameter))
    return OutOfDomain::exclude;
  const nlohmann::json& value = parameters[kOutOfDomainParameter];
  const auto handling =
      value.is_string() ? out_of_domain_from_string(value.get<std::string>()) : std::nullopt;
  if (!handling) throw InvalidInput(kOutOfDomainParameter, "must be \"exclude\" or \"clamp\"");
  return *handling;
}

nlohmann::json parameters_for_model(const ModelDescriptor& descriptor,
                                    const nlohmann::json& parameters) {
  nlohmann::json out = nlohmann::json::object();
  if (!parameters.is_object()) return out;
  for (const auto& [name, value] : parameters.items())
    if (descriptor.find_parameter(name) != nullptr) out[name] = value;
  return out;
}

QualityLevel quality_of(const nlohmann::json& parameters) {
  if (!parameters.is_object() || !parameters.contains(kQualityParameter))
    return QualityLevel::standard;
  const nlohmann::json& value = parameters[kQualityParameter];
  const auto level =
      value.is_string() ? parse_quality_level(value.get<std::string>()) : std::nullopt;
  if (!level)
    throw InvalidInput(kQualityParameter, "must be \"draft\", \"standard\" or \"reference\"");
  return *level;
}

ModelConfig config_for_model(const ModelDescriptor& descriptor, const nlohmann::json& parameters) {
  ModelConfig config;
  const nlohmann::json applied = parameters_for_model(descriptor, parameters);
  for (const auto& [name, value] : applied.items()) {
    const ParameterSpec& spec = *descriptor.find_parameter(name);
    if (spec.atmosphere && name == "albedo" && value.is_string() &&
        value.get<std::string>() == "grass") {
      config.atmosphere.ground_albedo.reset();
      continue;
    }
    if (!value.is_number()) throw std::invalid_argument(name + ": must be a number");
    const double number = value.get<double>();
    if (!spec.atmosphere)
      config.options[name] = number;
    else if (!set_atmosphere_parameter(config.atmosphere, name, number))
      throw std::logic_error("descriptor of " + descriptor.id +
                             " lists unknown atmosphere parameter " + name);
  }
  // The quality level's options, where the parameters do not give them.
  apply_quality_level(descriptor, quality_setting(descriptor.id, quality_of(parameters)),
                      config.options);
  return config;
}

std::vector<const ModelFactory*> resolve_models(const std::vector<std::string>& requested,
                                                std::span<const ModelFactory> available) {
  std::vector<const ModelFactory*> factories;
  const bool all = requested.empty() || (requested.size() == 1 && requested[0] == "all");
  if (all) {
    for (const ModelFactory& factory : available) factories.push_back(&factory);
    if (factories.empty()) throw std::invalid_argument("no model is registered");
    return factories;
  }
  std::string unknown;
  for (const std::string& id : requested) {
    const ModelFactory* found = nullptr;
    for (const ModelFactory& factory : available)
      if (factory.descriptor->id == id) found = &factory;
    if (found == nullptr)
      unknown += (unknown.empty() ? "" : ", ") + id;
    else
      factories.push_back(found);
  }
  if (!unknown.empty()) {
    std::string known;
    for (const ModelFactory& factory : available)
      known += (known.empty() ? "" : ", ") + factory.descriptor->id;
    throw std::invalid_argument("unknown model(s): " + unknown +
                                " (registered: " + (known.empty() ? "none" : known) + ")");
  }
  return factories;
}

std::shared_ptr<const SkyModel> provided_model(const ModelProvider& provider,
                                               const ModelFactory& factory,
                                               const ModelConfig& config) {
  for (;;) {
    try {
      return provider.model(factory, config);
    } catch (const ApiError& e) {
      if (e.code() != "model_not_ready") return nullptr;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
}

namespace {

// evaluate_model (models/evaluation/evaluate_model.h) on the provider's model when there is a
// provider and it supplies the model: the tables and per-sun states (kept by the model itself)
// are then those the sky endpoints use, built once for both. precompute_seconds: the time
// spent obtaining the models (0 when they were ready).
EvaluationResult evaluate_through(const ModelProvider* provider, const ModelFactory& factory,
                                  const ModelConfig& config,
                                  std::span<const MeasuredCapture> captures,
                                  const EvaluationOptions& options) {
  if (provider == nullptr) return evaluate_model(factory, config, captures, options);
  const auto start = std::chrono::steady_clock::now();
  const std::shared_ptr<const SkyModel> model = provided_model(*provider, factory, config);
  if (!model) return evaluate_model(factory, config, captures, options);
  std::shared_ptr<const SkyModel> fit_clamped;
  if (options.out_of_domain == OutOfDomain::clamp &&
      factory.descriptor->find_parameter(kClampNegativeFitOption) != nullptr &&
      option_or_default(*factory.descriptor, config, kClampNegativeFitOption) == 0.0) {
    ModelConfig clamped = config;
    clamped.options[kClampNegativeFitOption] = 1.0;
    fit_clamped = provided_model(*provider, factory, clamped);
    if (!fit_clamped) fit_clamped = factory.create(clamped, options.context);
  }
  const double precompute_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EvaluationResult result = evaluate_sky_model(*model, captures, options, fit_clamped.get());
  result.precompute_seconds = precompute_seconds;
  return result;
}

}  // namespace

EvaluationReport run_evaluation(storage::Database& db, const EvaluationRequest& request) {
  return run_evaluation(db, request, registered_models());
}

EvaluationReport run_evaluation(storage::Database& db, const EvaluationRequest& request,
                                std::span<const ModelFactory> available) {
  const std::vector<const ModelFactory*> factories = resolve_models(request.models, available);
  const PreparedDataset prepared = load_prepared_dataset(db, request.dataset);
  const std::vector<MeasuredCapture>& captures = prepared.captures;
  const std::string& steps = prepared.processing_steps;

  EvaluationOptions options = request.options;
  options.out_of_domain = out_of_domain_of(request.parameters);
  EvaluationReport report;
  report.dataset = request.dataset;
  report.out_of_domain = options.out_of_domain;
  report.min_wavelength_nm = request.options.min_wavelength_nm;
  report.max_wavelength_nm = request.options.max_wavelength_nm;
  storage::EvaluationRunRepository runs(db);
  for (const ModelFactory* factory_pointer : factories) {
    const ModelFactory& factory = *factory_pointer;
    const std::string& id = factory.descriptor->id;
    storage::NewRun run;
    run.dataset_id = prepared.dataset_id;
    run.job_id = request.job_id;
    run.model_id = id;
    run.model_version = factory.descriptor->version;
    // A stored fit named by the parameters, expanded now: "latest" is the newest when the run
    // starts (evaluation_fit.h).
    const nlohmann::json parameters =
        expand_evaluation_fit(db, request.parameters, *factory.descriptor);
    const ModelConfig config = config_for_model(*factory.descriptor, parameters);
    nlohmann::json applied = parameters_for_model(*factory.descriptor, parameters);
    if (parameters.contains(kFitParameter)) applied[kFitParameter] = parameters[kFitParameter];
    if (request.parameters.is_object() && request.parameters.contains(kOutOfDomainParameter))
      applied[kOutOfDomainParameter] = request.parameters[kOutOfDomainParameter];
    if (request.parameters.is_object() && request.parameters.contains(kQualityParameter))
      applied[kQualityParameter] = request.parameters[kQualityParameter];
    run.parameters = applied.dump();
    run.out_of_domain = std::string(to_string(options.out_of_domain));
    run.configuration = config.canonical_string();
    run.software_version = request.software_version;
    run.min_wavelength_nm = request.options.min_wavelength_nm;
    run.max_wavelength_nm = request.options.max_wavelength_nm;
    const std::int64_t run_id = runs.start(run);
    if (request.on_run_status) request.on_run_status(run_id, id, "running");
    try {
      EvaluationResult result =
          evaluate_through(request.provider, factory, config, captures, options);
      std::vector<storage::RunCaptureResult> per_capture;
      for (std::size_t i = 0; i < result.captures.size(); ++i) {
        const CaptureEvaluation& c = result.captures[i];
        storage::RunCaptureResult r;
        r.capture_id = prepared.capture_ids[i];
        r.sun_zenith_deg = c.sun_zenith_deg;
        r.sun_azimuth_deg = c.sun_azimuth_deg;
        r.rmse = c.rmse;
        r.answered = c.answered();
        r.values_compared = static_cast<std::int64_t>(c.values_compared);
        r.samples_compared = static_cast<std::int64_t>(c.samples.size());
        r.out_of_domain = stored_sample_handling(c);
        r.samples = stored_sample_errors(c, result.wavelengths_nm.size());
        per_capture.push_back(std::move(r));
      }
      runs.finish(run_id, result.rmse, result.precompute_seconds, result.evaluate_seconds, steps,
                  per_capture, result.wavelengths_nm);
      report.models.push_back({run_id, std::move(result)});
    } catch (const std::exception& e) {
      runs.fail(run_id, e.what());
      if (request.on_run_status) request.on_run_status(run_id, id, "failed");
      throw;
    }
    if (request.on_run_status) request.on_run_status(run_id, id, "succeeded");
  }
  return report;
}

}  // namespace clearsky::api
