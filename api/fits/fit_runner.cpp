// Stored atmosphere fits (fit_runner.h).
#include "api/fits/fit_runner.h"

#include <cmath>
#include <set>
#include <stdexcept>

#include "api/encode/fit_json.h"
#include "api/evaluation/broadband_evaluation_runner.h"
#include "api/evaluation/evaluation_runner.h"
#include "api/evaluation/evaluations_api.h"
#include "api/evaluation/prepared_dataset.h"
#include "api/fits/broadband_fit.h"
#include "api/request/sky_fit.h"
#include "models/core/invalid_input.h"
#include "models/registry.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/fit_repository.h"
#include "storage/repositories/irradiance_sample_repository.h"

namespace clearsky::api {

namespace {

FitBounds parse_bounds(const nlohmann::json& bounds) {
  FitBounds out;
  if (!bounds.is_object()) throw InvalidInput("bounds", "must be an object {name: [min, max]}");
  for (const auto& [name, range] : bounds.items()) {
    if (!range.is_array() || range.size() != 2 || !range[0].is_number() || !range[1].is_number())
      throw InvalidInput("bounds", name + ": must be [min, max]");
    out[name] = {range[0].get<double>(), range[1].get<double>()};
  }
  return out;
}

std::map<std::string, double> parse_search_options(const ModelDescriptor& descriptor,
                                                   const nlohmann::json& options) {
  if (!options.is_object()) throw InvalidInput("search_options", "must be an object");
  std::map<std::string, double> out;
  for (const auto& [name, value] : options.items()) {
    const ParameterSpec* spec = descriptor.find_parameter(name);
    if (spec == nullptr || spec->atmosphere)
      throw InvalidInput("search_options", name + " is not an option of " + descriptor.id);
    if (!value.is_number() || !(value.get<double>() >= spec->min_value) ||
        !(value.get<double>() <= spec->max_value))
      throw InvalidInput("search_options", name + ": must be a number in the option's range");
    out[name] = value.get<double>();
  }
  return out;
}

storage::NewFit new_fit(storage::Database& db, const FitRequest& request,
                        const CheckedFit& checked) {
  const auto dataset = storage::DatasetRepository(db).find(request.dataset);
  if (!dataset) throw std::invalid_argument("no dataset named '" + request.dataset + "'");
  storage::NewFit fit;
  fit.dataset_id = dataset->id;
  fit.model_id = checked.factory->descriptor->id;
  fit.model_version = checked.factory->descriptor->version;
  fit.free_parameters = free_parameters_json(checked.settings.parameters).dump();
  fit.fixed_parameters = checked.fixed_parameters.dump();
  fit.search_options = nlohmann::json(checked.settings.search_options).dump();
  fit.captures = nlohmann::json(request.captures).dump();
  fit.settings =
      nlohmann::json{{"per_capture", request.per_capture},
                     {"cross_validate", request.cross_validate},
                     {"max_refine_evaluations", request.max_refine_evaluations},
                     {"max_fold_refine_evaluations", request.max_fold_refine_evaluations},
                     {"uncertainty_fraction", checked.settings.uncertainty_fraction}}
          .dump();
  fit.software_version = request.software_version;
  return fit;
}

}  // namespace

CheckedFit check_fit_request(const FitRequest& request) {
  CheckedFit out;
  out.factory = find_model(request.model);
  if (out.factory == nullptr) throw InvalidInput("model", "unknown model '" + request.model + "'");
  const ModelDescriptor& descriptor = *out.factory->descriptor;
  const std::vector<std::string> names =
      request.free.empty() ? default_free_parameters(descriptor) : request.free;
  out.settings.parameters =
      make_free_parameters(descriptor, names, parse_bounds(request.bounds), request.grid);
  const ModelFactory* const models[] = {out.factory};
  const nlohmann::json parameters = parse_evaluation_parameters(request.parameters, models);
  // A fit starts from values given as they are; it does not expand a stored fit (that is for
  // the sky endpoints and evaluations, docs/fits.md "Using a fit").
  if (parameters.contains(kFitParameter))
    throw invalid_parameter(kFitParameter,
                            "a fit's parameters cannot name a stored fit: give values");
  out.fixed_parameters = parameters_for_model(descriptor, parameters);
  out.settings.config = config_for_model(descriptor, parameters);
  out.settings.evaluation.out_of_domain = out_of_domain_of(parameters);
  if (parameters.contains(kOutOfDomainParameter))
    out.fixed_parameters[kOutOfDomainParameter] = parameters[kOutOfDomainParameter];
  if (parameters.contains(kQualityParameter))
    out.fixed_parameters[kQualityParameter] = parameters[kQualityParameter];
  out.settings.evaluation.capture_threads = request.capture_threads;
  // A table option fixed in parameters is the standard setting; the search keeps the cheap one.
  out.settings.search_options = request.search_options
                                    ? parse_search_options(descriptor, *request.search_options)
                                    : cheap_search_options(descriptor);
  if (!(request.max_refine_evaluations >= 0 && request.max_refine_evaluations <= 10000))
    throw InvalidInput("max_refine_evaluations", "must be in [0, 10000]");
  if (!(request.max_fold_refine_evaluations >= 0 && request.max_fold_refine_evaluations <= 10000))
    throw InvalidInput("max_fold_refine_evaluations", "must be in [0, 10000]");
  out.settings.max_refine_evaluations = request.max_refine_evaluations;
  out.settings.max_fold_refine_evaluations = request.max_fold_refine_evaluations;
  out.settings.per_capture = request.per_capture;
  out.settings.cross_validate = request.cross_validate;
  out.settings.cancel = request.cancel;
  return out;
}

std::int64_t record_queued_fit(storage::Database& db, const FitRequest& request) {
  const CheckedFit checked = check_fit_request(request);
  storage::NewFit fit = new_fit(db, request, checked);
  fit.status = "queued";
  return storage::FitRepository(db).start(fit);
}

std::int64_t run_fit(storage::Database& db, const FitRequest& request,
                     std::optional<std::int64_t> queued_id) {
  CheckedFit checked = check_fit_request(request);
  storage::FitRepository fits(db);
  std::int64_t id = 0;
  if (queued_id) {
    id = *queued_id;
    fits.run(id);
  } else {
    id = fits.start(new_fit(db, request, checked));
  }
  try {
    if (is_broadband_dataset(db, request.dataset)) {
      // A broadband irradiance series (docs/fits.md "Fits to broadband irradiance").
      if (!request.captures.empty())
        throw InvalidInput("captures",
                           "dataset '" + request.dataset +
                               "' is a broadband irradiance series: it has no captures");
      const auto dataset = storage::DatasetRepository(db).find(request.dataset);
      checked.settings.progress = [&](double fraction, std::string_view stage) {
        if (request.progress) request.progress(fraction, stage);
        fits.progress(id, fraction, std::string(stage));
      };
      const FitResult result =
          fit_broadband(*checked.factory, storage::IrradianceSampleRepository(db).list(dataset->id),
                        checked.settings);
      fits.finish(id, fit_outcome(result));
      return id;
    }
    PreparedDataset prepared = load_prepared_dataset(db, request.dataset);
    std::vector<MeasuredCapture> captures;
    if (request.captures.empty()) {
      captures = std::move(prepared.captures);
    } else {
      std::set<std::string> wanted(request.captures.begin(), request.captures.end());
      for (MeasuredCapture& c : prepared.captures)
        if (wanted.erase(c.label) > 0) captures.push_back(std::move(c));
      if (!wanted.empty())
        throw InvalidInput("captures", "no capture labelled '" + *wanted.begin() +
                                           "' in dataset '" + request.dataset + "'");
    }
    double last_fraction = -1;
    std::string last_stage;
    checked.settings.progress = [&](double fraction, std::string_view stage) {
      if (request.progress) request.progress(fraction, stage);
      if (stage != last_stage || fraction >= last_fraction + 0.01) {
        last_stage = std::string(stage);
        last_fraction = fraction;
        fits.progress(id, fraction, last_stage);
      }
    };
    const FitResult result = fit_model(*checked.factory, captures, checked.settings);
    fits.finish(id, fit_outcome(result));
  } catch (const PrecomputeCancelled& e) {
    fits.fail(id, std::string("interrupted: the fit was cancelled (") + e.what() + ")",
              "interrupted");
    throw;
  } catch (const std::exception& e) {
    fits.fail(id, e.what());
    throw;
  }
  return id;
}

}  // namespace clearsky::api
