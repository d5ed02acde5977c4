// /v1/evaluations handlers (evaluations_api.h).
#include "api/evaluation/evaluations_api.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

#include "api/encode/iso8601_time.h"
#include "api/error/api_error.h"
#include "api/evaluation/broadband_evaluation_runner.h"
#include "api/evaluation/evaluation_fit.h"
#include "api/http/json_body.h"
#include "api/parse/iso8601_time.h"
#include "api/request/aerosols_option.h"
#include "api/request/sky_request.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/evaluation_run_repository.h"
#include "storage/repositories/irradiance_run_results.h"

namespace clearsky::api {
namespace {

nlohmann::ordered_json optional_number(const std::optional<double>& value) {
  if (!value || !std::isfinite(*value)) return nullptr;
  return *value;
}

template <typename T>
nlohmann::ordered_json optional_value(const std::optional<T>& value) {
  if (!value) return nullptr;
  return *value;
}

double time_of(const std::string& iso, const std::string& parameter) {
  return parse_iso8601_time(iso, parameter).unix_time_utc_s;
}

std::map<std::int64_t, std::string> dataset_names(storage::Database& db) {
  std::map<std::int64_t, std::string> names;
  for (const auto& d : storage::DatasetRepository(db).list()) names[d.id] = d.name;
  return names;
}

// A broadband run's per-component results (W/m2; docs/data-api.md "Evaluations of broadband
// irradiance"): empty for a run on captures. with_errors adds each sample's error, in the
// dataset's order by instant (null where not compared).
nlohmann::ordered_json irradiance_components_json(storage::Database& db, std::int64_t run_id,
                                                  bool with_errors) {
  nlohmann::ordered_json components = nlohmann::ordered_json::array();
  for (const storage::IrradianceRunResult& r :
       storage::IrradianceRunResultRepository(db).load(run_id)) {
    nlohmann::ordered_json c{{"component", r.component},
                             {"rmse_w_m2", optional_number(r.rmse_w_m2)},
                             {"mean_bias_w_m2", optional_number(r.mean_bias_w_m2)},
                             {"samples_compared", r.samples_compared}};
    if (with_errors) {
      nlohmann::ordered_json errors = nlohmann::ordered_json::array();
      for (double e : r.errors_w_m2) errors.push_back(optional_number(e));
      c["errors_w_m2"] = std::move(errors);
    }
    components.push_back(std::move(c));
  }
  return components;
}

// The samples a broadband run's pooled RMSE covers: every compared sample of every component
// (the run row counts captures' samples, none here).
std::int64_t pooled_samples_compared(const nlohmann::ordered_json& components) {
  std::int64_t n = 0;
  for (const auto& c : components) n += c["samples_compared"].get<std::int64_t>();
  return n;
}

// What a run's rmse is in: W/m2 on a broadband irradiance series, mW/(m2.sr.nm) on captures.
const char* rmse_unit(bool broadband) { return broadband ? "W/m2" : "mW/(m2.sr.nm)"; }

// A run's stored parameters (a JSON object text from schema version 4).
nlohmann::ordered_json stored_parameters_json(const std::string& text) {
  const auto parsed = nlohmann::ordered_json::parse(text, nullptr, false);
  return parsed.is_object() ? parsed : nlohmann::ordered_json::object();
}

}  // namespace

std::int64_t parse_id(const std::string& text, const std::string& parameter) {
  std::int64_t id = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), id);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || id <= 0)
    throw invalid_parameter(parameter, "\"" + text + "\" is not a positive integer id");
  return id;
}

nlohmann::json parse_evaluation_parameters(const nlohmann::json& parameters,
                                           std::span<const ModelFactory* const> models) {
  if (parameters.is_null()) return nlohmann::json::object();
  if (!parameters.is_object())
    throw invalid_parameter("parameters", "must be an object of parameter names and numbers");
  for (const auto& [name, value] : parameters.items()) {
    if (name == kOutOfDomainParameter) {
      // What is done with samples a model cannot answer: an evaluation's, no model's, parameter.
      try {
        out_of_domain_of(parameters);
      } catch (const std::invalid_argument& e) {
        throw from_invalid_argument(e);
      }
      continue;
    }
    if (name == kQualityParameter) {
      try {
        quality_of(parameters);
      } catch (const std::invalid_argument& e) {
        throw from_invalid_argument(e);
      }
      continue;
    }
    if (name == kFitParameter) {
      // A stored fit (evaluation_fit.h): read here, found and checked where the database is.
      evaluation_fit_reference(parameters);
      continue;
    }
    const bool grass = name == "albedo" && value.is_string() && value.get<std::string>() == "grass";
    if (!grass && !value.is_number()) throw invalid_parameter(name, "must be a number");
  }
  if (models.empty()) return parameters;
  for (const auto& [name, value] : parameters.items()) {
    if (name == kOutOfDomainParameter || name == kQualityParameter || name == kFitParameter)
      continue;
    std::vector<const ModelFactory*> takers;
    for (const ModelFactory* model : models)
      if (model->descriptor->find_parameter(name) != nullptr) takers.push_back(model);
    if (takers.empty()) {
      std::string ids;
      for (const ModelFactory* model : models)
        ids += (ids.empty() ? "" : ", ") + model->descriptor->id;
      throw ApiError(400, "unknown_parameter", name,
                     name + ": applies to none of the requested models (" + ids +
                         "); a parameter is refused unless one of them lists it "
                         "(GET /v1/models/{id})");
    }
    if (!value.is_number()) continue;  // albedo "grass"
    // Within the range of every requested model that takes it (e.g. Preetham's turbidity
    // starts at 2, the shared atmosphere's at 1), as the sky endpoints check it.
    const double number = value.get<double>();
    for (const ModelFactory* model : takers) {
      const ParameterSpec& spec = *model->descriptor->find_parameter(name);
      if (!(number >= spec.min_value && number <= spec.max_value)) {
        std::ostringstream message;
        message << "must be in [" << spec.min_value << ", " << spec.max_value << "] for "
                << model->descriptor->id;
        throw invalid_parameter(name, message.str());
      }
      if (spec.integer && number != std::floor(number))
        throw invalid_parameter(name, "must be an integer");
    }
    check_aerosols_option(name, number);
  }
  try {
    for (const ModelFactory* model : models)
      validate_config(*model->descriptor, config_for_model(*model->descriptor, parameters));
  } catch (const std::invalid_argument& e) {
    throw from_invalid_argument(e);
  }
  return parameters;
}

EvaluationRequest parse_evaluation_request(storage::Database& db, const std::string& body,
                                           std::span<const ModelFactory> available,
                                           const std::string& software_version) {
  nlohmann::json j = parse_client_json(body);
  if (!j.is_object()) throw ApiError::about(400, "invalid_body", "body", "must be a JSON object");
  for (const auto& [name, value] : j.items()) {
    if (name != "models" && name != "dataset" && name != "parameters")
      throw unknown_parameter(name, "POST /v1/evaluations");
  }
  EvaluationRequest request;
  request.software_version = software_version;
  if (!j.contains("dataset") || !j["dataset"].is_string())
    throw missing_parameter("dataset", "the name of a stored dataset");
  request.dataset = j["dataset"].get<std::string>();
  const auto dataset = storage::DatasetRepository(db).find(request.dataset);
  if (!dataset)
    throw ApiError(404, "unknown_dataset", "dataset",
                   "dataset: no dataset named '" + request.dataset + "'");
  const nlohmann::json models = j.value("models", nlohmann::json("all"));
  if (models.is_string()) {
    request.models = {models.get<std::string>()};
  } else if (models.is_array() && !models.empty()) {
    for (const auto& m : models) {
      if (!m.is_string()) throw invalid_parameter("models", "model ids must be strings");
      request.models.push_back(m.get<std::string>());
    }
  } else {
    throw invalid_parameter("models", "\"all\" or a non-empty array of model ids");
  }
  // On a broadband irradiance series "all" is the models with a broadband answer, and one
  // named without is refused here (422 naming models) rather than when the ticket runs.
  const bool broadband = dataset->kind == storage::kBroadbandIrradianceKind;
  std::vector<const ModelFactory*> factories;
  try {
    factories = broadband ? broadband_models(request.models, available)
                          : resolve_models(request.models, available);
  } catch (const std::invalid_argument& e) {
    throw ApiError(404, "unknown_model", "models", std::string("models: ") + e.what());
  }
  request.parameters =
      parse_evaluation_parameters(j.value("parameters", nlohmann::json()), factories);
  check_evaluation_fit(db, request.parameters, factories);
  return request;
}

EvaluationFilter parse_evaluation_filter(Parameters query) {
  EvaluationFilter f;
  f.model = query.text("model");
  f.dataset = query.text("dataset");
  if (const auto since = query.text("since")) f.since_unix_s = time_of(*since, "since");
  if (const auto until = query.text("until")) f.until_unix_s = time_of(*until, "until");
  f.status = query.text("status");
  if (f.status && *f.status != "running" && *f.status != "succeeded" && *f.status != "failed")
    throw invalid_parameter("status", "one of running, succeeded, failed");
  if (const auto job = query.text("job")) f.job_id = parse_id(*job, "job");
  if (const auto job = query.text("job_id")) {
    if (f.job_id) throw conflicting_parameters("job_id", "job");
    f.job_id = parse_id(*job, "job_id");
  }
  f.page = parse_page_request(query);
  query.reject_unused();
  return f;
}

ShowEvaluationOptions parse_show_evaluation_options(Parameters query) {
  ShowEvaluationOptions options;
  if (const auto samples = query.text("samples")) {
    if (*samples == "spectra")
      options.samples = SampleDetail::spectra;
    else if (*samples == "true" || *samples == "1")
      options.samples = SampleDetail::summary;
    else if (*samples == "false" || *samples == "0" || samples->empty())
      options.samples = SampleDetail::none;
    else
      throw invalid_parameter("samples", "\"" + *samples + "\" is not true, false or spectra");
  }
  options.capture = query.text("capture");
  query.reject_unused();
  return options;
}

ListPage list_evaluations(storage::Database& db, const EvaluationFilter& filter) {
  const PageRequest& page = filter.page;
  const auto names = dataset_names(db);
  storage::RunFilter where;
  if (filter.dataset) {
    for (const auto& [id, name] : names)
      if (name == *filter.dataset) where.dataset_id = id;
    if (!where.dataset_id)
      throw ApiError(404, "unknown_dataset", "dataset",
                     "dataset: no dataset named '" + *filter.dataset + "'");
  }
  where.model_id = filter.model;
  where.status = filter.status;
  where.job_id = filter.job_id;
  where.since_unix_s = filter.since_unix_s;
  where.until_unix_s = filter.until_unix_s;
  const auto runs = storage::EvaluationRunRepository(db).list(
      where, page.limit, page.cursor ? std::optional(id_from_cursor(*page.cursor)) : std::nullopt);
  std::map<std::int64_t, bool> broadband_datasets;
  for (const auto& d : storage::DatasetRepository(db).list())
    broadband_datasets[d.id] = d.kind == storage::kBroadbandIrradianceKind;
  ListPage out;
  out.limit = page.limit;
  for (const storage::RunRecord& run : runs.rows) {
    const auto dataset = names.find(run.dataset_id);
    const bool broadband = broadband_datasets[run.dataset_id];
    nlohmann::ordered_json components =
        broadband ? irradiance_components_json(db, run.id, false) : nlohmann::ordered_json::array();
    const nlohmann::ordered_json samples_compared =
        broadband && run.status == "succeeded"
            ? nlohmann::ordered_json(pooled_samples_compared(components))
            : optional_value(run.samples_compared);
    out.items.push_back(
        {{"id", run.id},
         {"dataset", dataset == names.end() ? nlohmann::ordered_json(nullptr)
                                            : nlohmann::ordered_json(dataset->second)},
         {"model", run.model_id},
         {"status", run.status},
         {"started", run.started_utc},
         {"finished", optional_value(run.finished_utc)},
         {"rmse", optional_number(run.rmse)},
         {"rmse_unit", rmse_unit(broadband)},
         {"samples_compared", samples_compared},
         {"irradiance_components", std::move(components)},
         {"job", optional_value(run.job_id)}});
  }
  if (runs.more) out.next_cursor = id_cursor(runs.rows.back().id);
  return out;
}

nlohmann::ordered_json show_evaluation(storage::Database& db, std::int64_t run_id,
                                       const ShowEvaluationOptions& options) {
  storage::EvaluationRunRepository repository(db);
  const auto run = repository.get(run_id, options.samples != SampleDetail::none);
  if (!run)
    throw ApiError(404, "unknown_evaluation", "id",
                   "id: no evaluation run " + std::to_string(run_id));
  const auto names = dataset_names(db);

  nlohmann::ordered_json history{
      {"previous_run", nullptr}, {"previous_rmse", nullptr}, {"rmse_changed", nullptr}};
  if (run->status == "succeeded" && run->rmse) {
    if (const auto other = repository.previous_like(*run)) {
      const double difference = std::abs(*run->rmse - *other->rmse);
      history = {{"previous_run", other->id},
                 {"previous_rmse", *other->rmse},
                 {"rmse_changed", difference > 1e-9 * std::max(1.0, std::abs(*other->rmse))}};
    }
  }

  nlohmann::ordered_json steps = nlohmann::ordered_json::array();
  std::istringstream lines(run->processing_steps);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) steps.push_back(line);
  nlohmann::ordered_json captures = nlohmann::ordered_json::array();
  for (const storage::RunCaptureResult& c : run->captures) {
    if (options.capture && c.capture_label != *options.capture) continue;
    nlohmann::ordered_json capture = {
        {"label", c.capture_label},
        {"time", format_iso8601_time(c.capture_time_utc_s, c.utc_offset_minutes)},
        {"sun_zenith", c.sun_zenith_deg},
        {"sun_azimuth", c.sun_azimuth_deg},
        {"rmse", c.answered ? nlohmann::ordered_json(c.rmse) : nlohmann::ordered_json(nullptr)},
        {"values_compared", c.values_compared},
        {"samples_compared", optional_value(c.samples_compared)},
        {"excluded", sample_handling_to_json(c.out_of_domain, "excluded")},
        {"clamped", sample_handling_to_json(c.out_of_domain, "clamped")}};
    if (options.samples != SampleDetail::none)
      capture["samples"] = c.samples ? samples_to_json(*c.samples, options.samples)
                                     : nlohmann::ordered_json(nullptr);
    captures.push_back(std::move(capture));
  }
  if (options.capture && captures.empty())
    throw ApiError(
        404, "unknown_capture", "capture",
        "capture: run " + std::to_string(run_id) + " has no capture '" + *options.capture + "'");
  const auto dataset = names.find(run->dataset_id);
  const auto dataset_record =
      dataset == names.end() ? std::nullopt : storage::DatasetRepository(db).find(dataset->second);
  const bool broadband =
      dataset_record && dataset_record->kind == storage::kBroadbandIrradianceKind;
  nlohmann::ordered_json out = {
      {"id", run->id},
      {"dataset", dataset == names.end() ? nlohmann::ordered_json(nullptr)
                                         : nlohmann::ordered_json(dataset->second)},
      {"model", run->model_id},
      {"model_version", run->model_version},
      {"parameters", stored_parameters_json(run->parameters)},
      {"software_version", run->software_version},
      {"wavelength_range_nm", {run->min_wavelength_nm, run->max_wavelength_nm}}};
  if (options.samples == SampleDetail::spectra)
    out["wavelengths_nm"] =
        run->wavelengths_nm ? nlohmann::ordered_json(*run->wavelengths_nm) : nullptr;
  out["job"] = optional_value(run->job_id);
  out["status"] = run->status;
  out["error"] = optional_value(run->error);
  out["started"] = run->started_utc;
  out["finished"] = optional_value(run->finished_utc);
  out["rmse"] = optional_number(run->rmse);
  out["rmse_unit"] = rmse_unit(broadband);
  out["irradiance_components"] =
      broadband ? irradiance_components_json(db, run->id, options.samples != SampleDetail::none)
                : nlohmann::ordered_json::array();
  out["out_of_domain"] = run->out_of_domain;
  out["samples_compared"] =
      broadband && run->status == "succeeded"
          ? nlohmann::ordered_json(pooled_samples_compared(out["irradiance_components"]))
          : optional_value(run->samples_compared);
  out["samples_excluded"] = optional_value(run->samples_excluded);
  out["samples_clamped"] = optional_value(run->samples_clamped);
  out["captures_unanswered"] = optional_value(run->captures_unanswered);
  out["timings"] = {{"precompute_seconds", optional_number(run->precompute_seconds)},
                    {"evaluate_seconds", optional_number(run->evaluate_seconds)}};
  out["processing_steps"] = std::move(steps);
  out["captures"] = std::move(captures);
  out["history"] = std::move(history);
  return out;
}

}  // namespace clearsky::api
