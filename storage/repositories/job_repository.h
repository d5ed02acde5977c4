// Scheduled evaluations: a named job evaluates models (ids or "all") against a dataset on a
// cron-style schedule; the scheduler (server/) records its last and next run. The schedule
// text is validated by the scheduler, not here. Ids are never reused (schema version 4); the
// runs of a deleted job keep its id. SQL on the jobs table lives only here.
// Thread-safety: as the Database it uses.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "storage/repositories/keyset_page.h"
#include "storage/sqlite/database.h"

namespace clearsky::storage {

struct JobRecord {
  std::int64_t id = 0;
  std::string name;
  std::string schedule;
  std::int64_t dataset_id = 0;
  std::string models;      // "all" or comma-separated model ids
  std::string parameters;  // parameter overrides, as the API received them
  bool paused = false;
  std::string created_utc;
  std::optional<std::string> last_run_utc;
  std::optional<std::string> next_run_utc;
  // Due occurrences skipped because the previous run was still going (schema version 8).
  std::int64_t skipped_count = 0;
  std::optional<std::string> last_skipped_utc;
  // The fit request run before each occurrence, as JSON; empty: none (schema version 11).
  std::string refit;
  // The fit the newest occurrence made (schema version 11).
  std::optional<std::int64_t> last_fit_id;
};

class JobRepository {
 public:
  explicit JobRepository(Database& db) : db_(db) {}
  // Throws SqliteError (constraint) when the name is taken or the dataset does not exist.
  std::int64_t create(const JobRecord& job);
  std::vector<JobRecord> list();  // by name
  // At most limit jobs by name, those after after_name when given.
  KeysetPage<JobRecord> list_page(std::int64_t limit,
                                  const std::optional<std::string>& after_name = std::nullopt);
  std::optional<JobRecord> get(std::int64_t id);
  bool set_paused(std::int64_t id, bool paused);
  bool record_run(std::int64_t id, const std::string& last_run_utc,
                  const std::optional<std::string>& next_run_utc);
  // Sets the next run time only (a job created or resumed).
  bool set_next_run(std::int64_t id, const std::optional<std::string>& next_run_utc);
  // Records a run only if next_run_utc still equals expected_next_run_utc (compare-and-set):
  // of two schedulers seeing the same due run, one claims it. False when not claimed.
  bool claim_run(std::int64_t id, const std::string& expected_next_run_utc,
                 const std::string& last_run_utc, const std::optional<std::string>& next_run_utc);
  // A due occurrence skipped because the previous run is still going: counts it, keeps its
  // time and sets the next run, in one statement. False when the job is gone.
  bool record_skip(std::int64_t id, const std::string& skipped_utc,
                   const std::optional<std::string>& next_run_utc);
  // The fit an occurrence of a re-fitting job made. False when the job is gone.
  bool set_last_fit(std::int64_t id, std::int64_t fit_id);
  bool remove(std::int64_t id);

 private:
  Database& db_;
};

}  // namespace clearsky::storage
