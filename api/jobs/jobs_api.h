// /v1/jobs, transport-free: scheduled evaluations (docs/architecture.md "The scheduler"). A job
// evaluates models against a stored dataset on a 5-field UTC cron schedule (cron_schedule.h);
// the scheduler (server/scheduler) runs it (docs/data-api.md "Jobs"). JSON:
//   create body: {"name", "schedule", "dataset", "models": "all" or [ids], "parameters": {...},
//                "refit": {...}} (parameters as POST /v1/evaluations; refit the body of POST
//                /v1/fits without dataset, job_refit.h; both optional)
//   a job:  {"id", "name", "schedule", "dataset", "models": [ids] or "all", "parameters",
//            "refit" (or null), "paused", "created", "last_run", "next_run" (ISO 8601 UTC or
//            null), "skipped_count", "last_skipped", "last_fit" (job_refit.h: the fit of the
//            newest occurrence, or null),
//            "last_result": [{"run", "model", "status", "started", "rmse"}] (the newest run of each
//            model the job evaluated)}
// The list is by name, paged (api/paging/list_page.h). Creating computes the next run from
// now and answers the job with its Location; resuming recomputes it from now (a paused job
// does not catch up). Deleting a job keeps its runs, which keep its id (never reused). Errors are ApiError: 400 body, schedule or parameter; 404 unknown job,
// dataset or model; 409 name taken.
// Thread-safety: each call uses the given Database from the calling thread only.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>

#include "api/evaluation/evaluation_runner.h"
#include "api/paging/list_page.h"
#include "api/resources/created_resource.h"
#include "storage/repositories/job_repository.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

CreatedResource create_job(storage::Database& db, const std::string& body,
                           std::span<const ModelFactory> available, double now_unix_s);
// limit and cursor from the query (400 for other parameters).
ListPage list_jobs(storage::Database& db, Parameters query = Parameters("GET /v1/jobs"));
// The path of a job.
std::string job_location(std::int64_t id);
nlohmann::ordered_json show_job(storage::Database& db, std::int64_t id);
nlohmann::ordered_json pause_job(storage::Database& db, std::int64_t id);
nlohmann::ordered_json resume_job(storage::Database& db, std::int64_t id, double now_unix_s);
nlohmann::ordered_json delete_job(storage::Database& db, std::int64_t id);

// The name of the job's dataset; empty when it is gone.
std::string job_dataset_name(storage::Database& db, const storage::JobRecord& job);

// The evaluation a job runs (its dataset by name, models, parameters, job id; with fit_id, the
// fit its occurrence made as the parameters' "fit"); throws std::invalid_argument when its
// dataset is gone or its parameters no longer parse.
EvaluationRequest job_evaluation_request(storage::Database& db, const storage::JobRecord& job,
                                         const std::string& software_version,
                                         std::optional<std::int64_t> fit_id = std::nullopt);

// Job times as stored: ISO 8601 UTC to the second ("2026-11-21T10:00:00Z").
std::string job_time_text(std::int64_t unix_s);

}  // namespace clearsky::api
