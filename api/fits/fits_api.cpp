// The fits of the HTTP API (fits_api.h).
#include "api/fits/fits_api.h"

#include <set>

#include "api/encode/fit_json.h"
#include "api/error/api_error.h"
#include "api/evaluation/evaluations_api.h"
#include "api/http/json_body.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/fit_repository.h"

namespace clearsky::api {

namespace {

constexpr const char* kEndpoint = "POST /v1/fits";

std::vector<std::string> string_list(const nlohmann::json& value, const std::string& member) {
  if (!value.is_array()) throw invalid_parameter(member, "must be an array of strings");
  std::vector<std::string> out;
  for (const auto& item : value) {
    if (!item.is_string()) throw invalid_parameter(member, "must be an array of strings");
    out.push_back(item.get<std::string>());
  }
  return out;
}

int whole_number(const nlohmann::json& value, const std::string& member) {
  if (!value.is_number_integer() || value.get<std::int64_t>() < 0 ||
      value.get<std::int64_t>() > 10000)
    throw invalid_parameter(member, "must be a whole number in [0, 10000]");
  return value.get<int>();
}

bool flag(const nlohmann::json& value, const std::string& member) {
  if (!value.is_boolean()) throw invalid_parameter(member, "must be true or false");
  return value.get<bool>();
}

}  // namespace

FitRequest parse_fit_request(storage::Database& db, const std::string& body,
                             const std::string& software_version) {
  const nlohmann::json j = parse_client_json(body);
  if (!j.is_object()) throw ApiError::about(400, "invalid_body", "body", "must be a JSON object");
  static const std::set<std::string> kMembers = {
      "dataset",         "model",           "free",           "bounds",      "grid",
      "captures",        "parameters",      "search_options", "per_capture", "cross_validate",
      "max_evaluations", "fold_evaluations"};
  for (const auto& [name, value] : j.items())
    if (!kMembers.contains(name)) throw unknown_parameter(name, kEndpoint);
  FitRequest request;
  request.software_version = software_version;
  if (!j.contains("dataset") || !j["dataset"].is_string())
    throw missing_parameter("dataset", "the name of a stored dataset");
  if (!j.contains("model") || !j["model"].is_string())
    throw missing_parameter("model", "the id of the model to fit");
  request.dataset = j["dataset"].get<std::string>();
  request.model = j["model"].get<std::string>();
  if (j.contains("free")) request.free = string_list(j["free"], "free");
  if (j.contains("bounds")) request.bounds = j["bounds"];
  if (j.contains("grid")) {
    if (!j["grid"].is_array()) throw invalid_parameter("grid", "must be an array of counts");
    for (const auto& count : j["grid"]) {
      if (!count.is_number_integer() || count.get<std::int64_t>() < 1 ||
          count.get<std::int64_t>() > 101)
        throw invalid_parameter("grid", "the counts must be whole numbers in [1, 101]");
      request.grid.push_back(count.get<int>());
    }
  }
  if (j.contains("captures")) request.captures = string_list(j["captures"], "captures");
  if (j.contains("parameters")) request.parameters = j["parameters"];
  if (j.contains("search_options")) request.search_options = j["search_options"];
  if (j.contains("per_capture")) request.per_capture = flag(j["per_capture"], "per_capture");
  if (j.contains("cross_validate"))
    request.cross_validate = flag(j["cross_validate"], "cross_validate");
  if (j.contains("max_evaluations"))
    request.max_refine_evaluations = whole_number(j["max_evaluations"], "max_evaluations");
  if (j.contains("fold_evaluations"))
    request.max_fold_refine_evaluations = whole_number(j["fold_evaluations"], "fold_evaluations");
  try {
    check_fit_request(request);
  } catch (const std::invalid_argument& e) {
    throw from_invalid_argument(e);
  }
  const auto dataset = storage::DatasetRepository(db).find(request.dataset);
  if (!dataset)
    throw ApiError(404, "unknown_dataset", "dataset",
                   "dataset: no dataset named '" + request.dataset + "'");
  for (const std::string& label : request.captures)
    if (!storage::CaptureRepository(db).find_by_label(dataset->id, label))
      throw invalid_parameter(
          "captures", "no capture labelled '" + label + "' in dataset '" + request.dataset + "'");
  return request;
}

ListPage list_fits(storage::Database& db, Parameters query) {
  const PageRequest page = parse_page_request(query);
  query.reject_unused();
  std::vector<storage::FitRecord> fits = storage::FitRepository(db).list(
      static_cast<int>(page.limit + 1), page.cursor ? id_from_cursor(*page.cursor) : 0);
  ListPage out;
  out.limit = page.limit;
  const bool more = fits.size() > static_cast<std::size_t>(page.limit);
  if (more) fits.resize(static_cast<std::size_t>(page.limit));
  for (const storage::FitRecord& fit : fits)
    out.items.push_back(nlohmann::ordered_json(fit_to_json(fit, false)));
  if (more) out.next_cursor = id_cursor(fits.back().id);
  return out;
}

bool parse_show_fit_history(Parameters query) {
  const bool history = query.boolean_or("history", false);
  query.reject_unused();
  return history;
}

nlohmann::json show_fit(storage::Database& db, std::int64_t id, bool with_history) {
  const auto fit = storage::FitRepository(db).get(id);
  if (!fit) throw ApiError(404, "unknown_fit", "id", "id: no fit " + std::to_string(id));
  return fit_to_json(*fit, with_history);
}

std::string fit_location(std::int64_t id) { return "/v1/fits/" + std::to_string(id); }

}  // namespace clearsky::api
