// Finding the stored fit a request names (stored_fit_values.h).
#include "api/fits/stored_fit_values.h"

#include <charconv>

#include "api/error/api_error.h"
#include "api/routes/data_access.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/fit_repository.h"

namespace clearsky::api {
namespace {

constexpr std::string_view kLatest = "latest";

ApiError unknown_fit(const std::string& reason) {
  return ApiError::about(404, "unknown_fit", kFitParameter, reason);
}

// The fit's values from its stored result ({"values": {name: value}}), in the order of its
// free parameters.
AppliedFit applied_fit(const storage::FitRecord& record) {
  AppliedFit fit;
  fit.id = record.id;
  fit.model_id = record.fit.model_id;
  fit.model_version = record.fit.model_version;
  fit.dataset = record.dataset;
  const nlohmann::json result = nlohmann::json::parse(record.outcome->result);
  const nlohmann::json free = nlohmann::json::parse(record.fit.free_parameters);
  for (const auto& parameter : free) {
    const std::string name = parameter.at("name").get<std::string>();
    fit.values.emplace_back(name, result.at("values").at(name).get<double>());
  }
  return fit;
}

AppliedFit checked_succeeded(const std::optional<storage::FitRecord>& record, std::int64_t id) {
  if (!record) throw unknown_fit("no fit " + std::to_string(id));
  if (record->fit.status != "succeeded" || !record->outcome) {
    throw ApiError::about(409, "fit_not_succeeded", kFitParameter,
                          "fit " + std::to_string(id) + " is " + record->fit.status +
                              "; only a succeeded fit has values to use");
  }
  return applied_fit(*record);
}

}  // namespace

FitReference parse_fit_reference(const std::string& text) {
  FitReference reference;
  if (text == kLatest) return reference;
  if (text.starts_with(std::string(kLatest) + ':')) {
    reference.dataset = text.substr(kLatest.size() + 1);
    if (reference.dataset->empty())
      throw invalid_parameter(kFitParameter, "latest: needs a dataset name after the colon");
    return reference;
  }
  std::int64_t id = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), id);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || id <= 0) {
    throw invalid_parameter(kFitParameter, "\"" + text +
                                               "\" is not a fit id (a positive integer), latest "
                                               "or latest:DATASET");
  }
  reference.id = id;
  return reference;
}

AppliedFit find_succeeded_fit(storage::Database& db, std::int64_t id) {
  return checked_succeeded(storage::FitRepository(db).get(id), id);
}

AppliedFit find_applied_fit(storage::Database& db, const FitReference& reference,
                            const ModelDescriptor& descriptor) {
  if (reference.id) {
    AppliedFit fit = find_succeeded_fit(db, *reference.id);
    if (fit.model_id != descriptor.id) {
      throw ApiError::about(409, "fit_model_mismatch", kFitParameter,
                            "fit " + std::to_string(fit.id) + " is a fit of " + fit.model_id +
                                ", not of " + descriptor.id);
    }
    return fit;
  }
  std::optional<std::int64_t> dataset_id;
  std::string where;
  if (reference.dataset) {
    const auto dataset = storage::DatasetRepository(db).find(*reference.dataset);
    if (!dataset) throw unknown_fit("no dataset named '" + *reference.dataset + "'");
    dataset_id = dataset->id;
    where = " on dataset " + *reference.dataset;
  }
  const auto latest = storage::FitRepository(db).latest_succeeded(descriptor.id, dataset_id);
  if (!latest) throw unknown_fit("no succeeded fit of " + descriptor.id + where);
  AppliedFit fit = applied_fit(*latest);
  fit.latest = true;
  return fit;
}

FitLookup stored_fit_lookup(const ApiContext& context) {
  return [&context](const std::string& text, const ModelDescriptor& descriptor) {
    // Read before the database is looked for, so that a malformed value is a 400 everywhere.
    const FitReference reference = parse_fit_reference(text);
    if (context.data == nullptr) throw no_database(kFitParameter);
    storage::Database db = open_database(context);
    return find_applied_fit(db, reference, descriptor);
  };
}

}  // namespace clearsky::api
