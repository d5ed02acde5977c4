// SQL of the jobs table (job_repository.h).
#include "storage/repositories/job_repository.h"

#include "storage/repositories/utc_clock.h"

namespace clearsky::storage {
namespace {

constexpr const char* kJobSelect =
    "SELECT id, name, schedule, dataset_id, models, parameters, paused, created_utc, last_run_utc, "
    "next_run_utc, skipped_count, last_skipped_utc, refit, last_fit_id"
    " FROM jobs";

JobRecord read_job(const Statement& row) {
  JobRecord job;
  job.id = row.column_int64(0);
  job.name = row.column_text(1);
  job.schedule = row.column_text(2);
  job.dataset_id = row.column_int64(3);
  job.models = row.column_text(4);
  job.parameters = row.column_text(5);
  job.paused = row.column_int64(6) != 0;
  job.created_utc = row.column_text(7);
  if (!row.is_null(8)) job.last_run_utc = row.column_text(8);
  if (!row.is_null(9)) job.next_run_utc = row.column_text(9);
  job.skipped_count = row.column_int64(10);
  if (!row.is_null(11)) job.last_skipped_utc = row.column_text(11);
  if (!row.is_null(12)) job.refit = row.column_text(12);
  if (!row.is_null(13)) job.last_fit_id = row.column_int64(13);
  return job;
}

}  // namespace

std::int64_t JobRepository::create(const JobRecord& job) {
  // The refit column (schema version 11) only when the job re-fits: a job without one is
  // written as before, also to the older schemas the migration tests fill.
  auto statement =
      db_.prepare(job.refit.empty()
                      ? "INSERT INTO jobs (name, schedule, dataset_id, models, parameters, paused, "
                        "created_utc, next_run_utc) VALUES (?, ?, ?, ?, ?, ?, ?, ?)"
                      : "INSERT INTO jobs (name, schedule, dataset_id, models, parameters, paused, "
                        "created_utc, next_run_utc, refit) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)");
  statement.bind(1, job.name)
      .bind(2, job.schedule)
      .bind(3, job.dataset_id)
      .bind(4, job.models)
      .bind(5, job.parameters)
      .bind(6, job.paused ? 1 : 0)
      .bind(7, utc_now_iso8601());
  if (job.next_run_utc)
    statement.bind(8, *job.next_run_utc);
  else
    statement.bind_null(8);
  if (!job.refit.empty()) statement.bind(9, job.refit);
  statement.run();
  return db_.last_insert_rowid();
}

std::vector<JobRecord> JobRepository::list() {
  auto query = db_.prepare(std::string(kJobSelect) + " ORDER BY name");
  std::vector<JobRecord> jobs;
  while (query.step()) jobs.push_back(read_job(query));
  return jobs;
}

KeysetPage<JobRecord> JobRepository::list_page(std::int64_t limit,
                                               const std::optional<std::string>& after_name) {
  auto query = db_.prepare(std::string(kJobSelect) +
                           " WHERE ?1 IS NULL OR name > ?1 ORDER BY name LIMIT ?2");
  if (after_name)
    query.bind(1, *after_name);
  else
    query.bind_null(1);
  query.bind(2, limit + 1);
  std::vector<JobRecord> jobs;
  while (query.step()) jobs.push_back(read_job(query));
  return keyset_page(std::move(jobs), limit);
}

std::optional<JobRecord> JobRepository::get(std::int64_t id) {
  auto query = db_.prepare(std::string(kJobSelect) + " WHERE id = ?");
  query.bind(1, id);
  if (!query.step()) return std::nullopt;
  return read_job(query);
}

bool JobRepository::set_paused(std::int64_t id, bool paused) {
  auto statement = db_.prepare("UPDATE jobs SET paused = ? WHERE id = ?");
  statement.bind(1, paused ? 1 : 0).bind(2, id);
  statement.run();
  return db_.changes() > 0;
}

bool JobRepository::record_run(std::int64_t id, const std::string& last_run_utc,
                               const std::optional<std::string>& next_run_utc) {
  auto statement = db_.prepare("UPDATE jobs SET last_run_utc = ?, next_run_utc = ? WHERE id = ?");
  statement.bind(1, last_run_utc);
  if (next_run_utc)
    statement.bind(2, *next_run_utc);
  else
    statement.bind_null(2);
  statement.bind(3, id);
  statement.run();
  return db_.changes() > 0;
}

bool JobRepository::set_last_fit(std::int64_t id, std::int64_t fit_id) {
  auto statement = db_.prepare("UPDATE jobs SET last_fit_id = ? WHERE id = ?");
  statement.bind(1, fit_id).bind(2, id);
  statement.run();
  return db_.changes() > 0;
}

bool JobRepository::record_skip(std::int64_t id, const std::string& skipped_utc,
                                const std::optional<std::string>& next_run_utc) {
  auto statement = db_.prepare(
      "UPDATE jobs SET skipped_count = skipped_count + 1, last_skipped_utc = ?, "
      "next_run_utc = ? WHERE id = ?");
  statement.bind(1, skipped_utc);
  if (next_run_utc)
    statement.bind(2, *next_run_utc);
  else
    statement.bind_null(2);
  statement.bind(3, id);
  statement.run();
  return db_.changes() > 0;
}

bool JobRepository::set_next_run(std::int64_t id, const std::optional<std::string>& next_run_utc) {
  auto statement = db_.prepare("UPDATE jobs SET next_run_utc = ? WHERE id = ?");
  if (next_run_utc)
    statement.bind(1, *next_run_utc);
  else
    statement.bind_null(1);
  statement.bind(2, id);
  statement.run();
  return db_.changes() > 0;
}

bool JobRepository::claim_run(std::int64_t id, const std::string& expected_next_run_utc,
                              const std::string& last_run_utc,
                              const std::optional<std::string>& next_run_utc) {
  auto statement = db_.prepare(
      "UPDATE jobs SET last_run_utc = ?, next_run_utc = ? WHERE id = ? AND next_run_utc = ?");
  statement.bind(1, last_run_utc);
  if (next_run_utc)
    statement.bind(2, *next_run_utc);
  else
    statement.bind_null(2);
  statement.bind(3, id).bind(4, expected_next_run_utc);
  statement.run();
  return db_.changes() > 0;
}

bool JobRepository::remove(std::int64_t id) {
  auto statement = db_.prepare("DELETE FROM jobs WHERE id = ?");
  statement.bind(1, id);
  statement.run();
  return db_.changes() > 0;
}

}  // namespace clearsky::storage
