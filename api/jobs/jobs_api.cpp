// /v1/jobs handlers (jobs_api.h).
#include "api/jobs/jobs_api.h"

#include <cmath>
#include <set>

#include "api/encode/iso8601_time.h"
#include "api/error/api_error.h"
#include "api/evaluation/evaluations_api.h"
#include "api/http/json_body.h"
#include "api/jobs/cron_schedule.h"
#include "api/jobs/job_refit.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/evaluation_run_repository.h"

namespace clearsky::api {
namespace {

std::vector<std::string> split_models(const std::string& text) {
  std::vector<std::string> models;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    if (comma > start) models.push_back(text.substr(start, comma - start));
    start = comma + 1;
  }
  return models;
}

storage::JobRecord find_job(storage::Database& db, std::int64_t id) {
  auto job = storage::JobRepository(db).get(id);
  if (!job) throw ApiError(404, "unknown_job", "id", "id: no job " + std::to_string(id));
  return *job;
}

nlohmann::ordered_json optional_text(const std::optional<std::string>& text) {
  if (!text) return nullptr;
  return *text;
}

std::string dataset_name_of(storage::Database& db, std::int64_t dataset_id) {
  for (const auto& d : storage::DatasetRepository(db).list())
    if (d.id == dataset_id) return d.name;
  return {};
}

nlohmann::ordered_json job_json(storage::Database& db, const storage::JobRecord& job) {
  const std::string dataset_name = dataset_name_of(db, job.dataset_id);
  nlohmann::ordered_json models;
  if (job.models == "all") {
    models = "all";
  } else {
    models = nlohmann::ordered_json::array();
    for (const std::string& m : split_models(job.models)) models.push_back(m);
  }
  // The newest run of each model this job evaluated.
  nlohmann::ordered_json last_result = nlohmann::ordered_json::array();
  std::set<std::string> seen;
  for (const auto& run : storage::EvaluationRunRepository(db).list(job.dataset_id)) {
    if (run.job_id != job.id || !seen.insert(run.model_id).second) continue;
    last_result.push_back(
        {{"run", run.id},
         {"model", run.model_id},
         {"status", run.status},
         {"started", run.started_utc},
         {"rmse", run.rmse && std::isfinite(*run.rmse) ? nlohmann::ordered_json(*run.rmse)
                                                       : nlohmann::ordered_json(nullptr)}});
  }
  return {{"id", job.id},
          {"name", job.name},
          {"schedule", job.schedule},
          {"dataset", dataset_name},
          {"models", std::move(models)},
          {"parameters", job.parameters.empty() ? nlohmann::ordered_json::object()
                                                : nlohmann::ordered_json::parse(job.parameters)},
          {"refit",
           job.refit.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json::parse(job.refit)},
          {"paused", job.paused},
          {"created", job.created_utc},
          {"last_run", optional_text(job.last_run_utc)},
          {"next_run", optional_text(job.next_run_utc)},
          {"skipped_count", job.skipped_count},
          {"last_skipped", optional_text(job.last_skipped_utc)},
          {"last_fit", last_fit_json(db, job)},
          {"last_result", std::move(last_result)}};
}

std::optional<std::string> next_run_text(const std::string& schedule, double now_unix_s) {
  const auto next =
      CronSchedule::parse(schedule).next_after(static_cast<std::int64_t>(std::floor(now_unix_s)));
  if (!next) return std::nullopt;
  return job_time_text(*next);
}

}  // namespace

std::string job_time_text(std::int64_t unix_s) {
  return format_iso8601_time(static_cast<double>(unix_s), 0, true);
}

std::string job_location(std::int64_t id) { return "/v1/jobs/" + std::to_string(id); }

CreatedResource create_job(storage::Database& db, const std::string& body,
                           std::span<const ModelFactory> available, double now_unix_s) {
  nlohmann::json j = parse_client_json(body);
  if (!j.is_object()) throw ApiError::about(400, "invalid_body", "body", "must be a JSON object");
  for (const auto& [name, value] : j.items())
    if (name != "name" && name != "schedule" && name != "dataset" && name != "models" &&
        name != "parameters" && name != "refit")
      throw unknown_parameter(name, "POST /v1/jobs");
  if (!j.contains("name") || !j["name"].is_string() || j["name"].get<std::string>().empty())
    throw missing_parameter("name", "a unique job name");
  if (!j.contains("schedule") || !j["schedule"].is_string())
    throw missing_parameter("schedule", "5 cron fields, UTC");
  storage::JobRecord job;
  job.name = j["name"].get<std::string>();
  job.schedule = j["schedule"].get<std::string>();
  try {
    CronSchedule::parse(job.schedule);
  } catch (const std::invalid_argument& e) {
    throw invalid_parameter("schedule",
                            std::string(e.what()).substr(std::string("schedule: ").size()));
  }
  const bool refits = j.contains("refit") && !j["refit"].is_null();
  // Each occurrence evaluates with its own new fit (job_refit.h): no other fit besides.
  if (refits && j.contains("parameters") && j["parameters"].is_object() &&
      j["parameters"].contains("fit"))
    throw conflicting_parameters("refit", "parameters.fit");
  // The evaluation part is checked as POST /v1/evaluations checks it.
  nlohmann::json evaluation{{"dataset", j.value("dataset", nlohmann::json())},
                            {"models", j.value("models", nlohmann::json("all"))}};
  if (j.contains("parameters")) evaluation["parameters"] = j["parameters"];
  const EvaluationRequest request = parse_evaluation_request(db, evaluation.dump(), available, "");
  job.dataset_id = storage::DatasetRepository(db).find(request.dataset)->id;
  if (request.models.size() == 1 && request.models[0] == "all") {
    job.models = "all";
  } else {
    for (const std::string& m : request.models) job.models += (job.models.empty() ? "" : ",") + m;
  }
  job.parameters =
      j.contains("parameters") && !j["parameters"].is_null() ? j["parameters"].dump() : "";
  // The fit of each occurrence is checked as POST /v1/fits checks it (job_refit.h).
  if (refits) {
    parse_job_refit(db, j["refit"], request.dataset, request.models,
                    j.value("parameters", nlohmann::json()), "");
    job.refit = j["refit"].dump();
  }
  job.next_run_utc = next_run_text(job.schedule, now_unix_s);
  storage::JobRepository jobs(db);
  for (const auto& existing : jobs.list())
    if (existing.name == job.name)
      throw ApiError(409, "conflict", "name", "name: a job named '" + job.name + "' exists");
  const std::int64_t id = jobs.create(job);
  return {job_json(db, find_job(db, id)), job_location(id)};
}

ListPage list_jobs(storage::Database& db, Parameters query) {
  const PageRequest request = parse_page_request(query);
  query.reject_unused();
  const auto jobs = storage::JobRepository(db).list_page(
      request.limit,
      request.cursor ? std::optional(name_from_cursor(*request.cursor)) : std::nullopt);
  ListPage page;
  page.limit = request.limit;
  for (const auto& job : jobs.rows) page.items.push_back(job_json(db, job));
  if (jobs.more) page.next_cursor = name_cursor(jobs.rows.back().name);
  return page;
}

nlohmann::ordered_json show_job(storage::Database& db, std::int64_t id) {
  return job_json(db, find_job(db, id));
}

nlohmann::ordered_json pause_job(storage::Database& db, std::int64_t id) {
  find_job(db, id);
  storage::JobRepository(db).set_paused(id, true);
  return show_job(db, id);
}

nlohmann::ordered_json resume_job(storage::Database& db, std::int64_t id, double now_unix_s) {
  const storage::JobRecord job = find_job(db, id);
  storage::Transaction transaction(db);
  storage::JobRepository jobs(db);
  jobs.set_paused(id, false);
  jobs.set_next_run(id, next_run_text(job.schedule, now_unix_s));
  transaction.commit();
  return show_job(db, id);
}

nlohmann::ordered_json delete_job(storage::Database& db, std::int64_t id) {
  if (!storage::JobRepository(db).remove(id))
    throw ApiError(404, "unknown_job", "id", "id: no job " + std::to_string(id));
  return {{"deleted", id}};
}

std::string job_dataset_name(storage::Database& db, const storage::JobRecord& job) {
  return dataset_name_of(db, job.dataset_id);
}

EvaluationRequest job_evaluation_request(storage::Database& db, const storage::JobRecord& job,
                                         const std::string& software_version,
                                         std::optional<std::int64_t> fit_id) {
  EvaluationRequest request;
  request.dataset = dataset_name_of(db, job.dataset_id);
  if (request.dataset.empty())
    throw std::invalid_argument("job " + job.name + ": its dataset no longer exists");
  request.models = split_models(job.models);
  nlohmann::json parameters =
      job.parameters.empty() ? nlohmann::json() : nlohmann::json::parse(job.parameters);
  // The occurrence's own fit (job_refit.h): applies to the fitted model only.
  if (fit_id) parameters["fit"] = *fit_id;
  request.parameters = parse_evaluation_parameters(parameters);
  request.software_version = software_version;
  request.job_id = job.id;
  return request;
}

}  // namespace clearsky::api
