// SQL of the evaluation_runs and evaluation_capture_results tables
// (evaluation_run_repository.h).
#include "storage/repositories/evaluation_run_repository.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string_view>

#include "models/core/content_hash.h"
#include "storage/repositories/utc_clock.h"
#include "storage/sqlite/blob.h"

namespace clearsky::storage {
namespace {

constexpr const char* kRunSelect =
    "SELECT id, dataset_id, job_id, model_id, model_version, parameters, software_version,"
    " min_wavelength_nm, max_wavelength_nm, started_utc, finished_utc, status, error, rmse,"
    " precompute_seconds, evaluate_seconds, processing_steps, wavelengths_nm, configuration,"
    " out_of_domain, samples_compared, samples_excluded, samples_clamped, captures_unanswered,"
    " compared_samples FROM evaluation_runs";

std::optional<double> optional_double(const Statement& row, int column) {
  if (row.is_null(column)) return std::nullopt;
  return row.column_double(column);
}

std::optional<std::string> optional_text(const Statement& row, int column) {
  if (row.is_null(column)) return std::nullopt;
  return row.column_text(column);
}

std::optional<std::int64_t> optional_int(const Statement& row, int column) {
  if (row.is_null(column)) return std::nullopt;
  return row.column_int64(column);
}

void bind_optional_int(Statement& statement, int index, std::optional<std::int64_t> value) {
  if (value)
    statement.bind(index, *value);
  else
    statement.bind_null(index);
}

RunRecord read_run(const Statement& row) {
  RunRecord r;
  r.id = row.column_int64(0);
  r.dataset_id = row.column_int64(1);
  if (!row.is_null(2)) r.job_id = row.column_int64(2);
  r.model_id = row.column_text(3);
  r.model_version = row.column_text(4);
  r.parameters = row.column_text(5);
  r.software_version = row.column_text(6);
  r.min_wavelength_nm = row.column_double(7);
  r.max_wavelength_nm = row.column_double(8);
  r.started_utc = row.column_text(9);
  r.finished_utc = optional_text(row, 10);
  r.status = row.column_text(11);
  r.error = optional_text(row, 12);
  r.rmse = optional_double(row, 13);
  r.precompute_seconds = optional_double(row, 14);
  r.evaluate_seconds = optional_double(row, 15);
  r.processing_steps = row.column_text(16);
  if (!row.is_null(17)) r.wavelengths_nm = decode_doubles(row.column_blob(17));
  r.configuration = row.column_text(18);
  r.out_of_domain = row.column_text(19);
  r.samples_compared = optional_int(row, 20);
  r.samples_excluded = optional_int(row, 21);
  r.samples_clamped = optional_int(row, 22);
  r.captures_unanswered = optional_int(row, 23);
  r.compared_samples = optional_text(row, 24);
  return r;
}

// The id of a stored blob with these bytes, stored now if there is none: repeated identical
// runs share one copy.
std::int64_t store_sample_errors(Database& db, const std::vector<std::byte>& bytes) {
  const auto hash = static_cast<std::int64_t>(
      fnv1a_64(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size())));
  auto find =
      db.prepare("SELECT id FROM evaluation_sample_errors WHERE content_hash = ? AND data = ?");
  find.bind(1, hash).bind_blob(2, bytes);
  if (find.step()) return find.column_int64(0);
  auto insert =
      db.prepare("INSERT INTO evaluation_sample_errors (content_hash, data) VALUES (?, ?)");
  insert.bind(1, hash).bind_blob(2, bytes);
  insert.run();
  return db.last_insert_rowid();
}

}  // namespace

std::int64_t EvaluationRunRepository::start(const NewRun& run) {
  auto statement = db_.prepare(
      "INSERT INTO evaluation_runs (dataset_id, job_id, model_id, model_version, parameters,"
      " software_version, min_wavelength_nm, max_wavelength_nm, started_utc, configuration,"
      " out_of_domain, status) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, 'running')");
  statement.bind(1, run.dataset_id);
  if (run.job_id)
    statement.bind(2, *run.job_id);
  else
    statement.bind_null(2);
  statement.bind(3, run.model_id)
      .bind(4, run.model_version)
      .bind(5, run.parameters)
      .bind(6, run.software_version)
      .bind(7, run.min_wavelength_nm)
      .bind(8, run.max_wavelength_nm)
      .bind(9, utc_now_iso8601())
      .bind(10, run.configuration)
      .bind(11, run.out_of_domain);
  statement.run();
  return db_.last_insert_rowid();
}

void EvaluationRunRepository::finish(std::int64_t run_id, double rmse, double precompute_seconds,
                                     double evaluate_seconds, const std::string& processing_steps,
                                     const std::vector<RunCaptureResult>& captures,
                                     std::span<const double> wavelengths_nm) {
  for (const RunCaptureResult& c : captures)
    if (c.samples && c.samples->wavelength_count != wavelengths_nm.size())
      throw std::invalid_argument("run " + std::to_string(run_id) + ": sample errors of " +
                                  std::to_string(c.samples->wavelength_count) +
                                  " wavelengths, run of " + std::to_string(wavelengths_nm.size()));
  Transaction transaction(db_);
  auto insert = db_.prepare(
      "INSERT INTO evaluation_capture_results (run_id, capture_id, sun_zenith_deg, "
      "sun_azimuth_deg, rmse,"
      " values_compared, sample_errors_id, samples_compared, out_of_domain)"
      " VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)");
  auto label_of = db_.prepare("SELECT label FROM captures WHERE id = ?");
  std::vector<std::pair<std::string, std::string>> key_lines;
  std::optional<std::int64_t> samples_compared = 0;
  std::int64_t samples_excluded = 0, samples_clamped = 0, captures_unanswered = 0;
  for (const RunCaptureResult& c : captures) {
    const std::string handling = encode_sample_handling(c.out_of_domain);
    label_of.reset();
    label_of.bind(1, c.capture_id);
    key_lines.emplace_back(label_of.step() ? label_of.column_text(0) : std::string(), handling);
    if (samples_compared && c.samples_compared)
      *samples_compared += *c.samples_compared;
    else
      samples_compared.reset();
    std::vector<std::int32_t> clamped;
    for (const SampleHandling& h : c.out_of_domain) {
      if (h.handling == "excluded")
        samples_excluded += static_cast<std::int64_t>(h.indices.size());
      else
        clamped.insert(clamped.end(), h.indices.begin(), h.indices.end());
    }
    std::sort(clamped.begin(), clamped.end());
    samples_clamped += std::unique(clamped.begin(), clamped.end()) - clamped.begin();
    if (!c.answered) ++captures_unanswered;
    const std::int64_t samples_id =
        c.samples ? store_sample_errors(db_, encode_sample_errors(*c.samples)) : 0;
    insert.reset();
    insert.bind(1, run_id)
        .bind(2, c.capture_id)
        .bind(3, c.sun_zenith_deg)
        .bind(4, c.sun_azimuth_deg);
    if (c.answered)
      insert.bind(5, c.rmse);
    else
      insert.bind_null(5);
    insert.bind(6, c.values_compared);
    if (c.samples)
      insert.bind(7, samples_id);
    else
      insert.bind_null(7);
    bind_optional_int(insert, 8, c.samples_compared);
    insert.bind(9, handling);
    insert.run();
  }
  auto update = db_.prepare(
      "UPDATE evaluation_runs SET status = 'succeeded', finished_utc = ?, rmse = ?, "
      "precompute_seconds = ?,"
      " evaluate_seconds = ?, processing_steps = ?, wavelengths_nm = ?, samples_compared = ?,"
      " samples_excluded = ?, samples_clamped = ?, captures_unanswered = ?,"
      " compared_samples = ? WHERE id = ?");
  update.bind(1, utc_now_iso8601());
  if (std::isfinite(rmse))
    update.bind(2, rmse);
  else
    update.bind_null(2);
  update.bind(3, precompute_seconds).bind(4, evaluate_seconds).bind(5, processing_steps);
  if (wavelengths_nm.empty())
    update.bind_null(6);
  else
    update.bind_blob(6, encode_doubles(wavelengths_nm));
  bind_optional_int(update, 7, samples_compared);
  update.bind(8, samples_excluded)
      .bind(9, samples_clamped)
      .bind(10, captures_unanswered)
      .bind(11, compared_samples_key(std::move(key_lines)))
      .bind(12, run_id);
  update.run();
  transaction.commit();
}

void EvaluationRunRepository::fail(std::int64_t run_id, const std::string& error) {
  auto update = db_.prepare(
      "UPDATE evaluation_runs SET status = 'failed', finished_utc = ?, error = ? WHERE id = ?");
  update.bind(1, utc_now_iso8601()).bind(2, error).bind(3, run_id);
  update.run();
}

int EvaluationRunRepository::fail_unfinished(const std::string& error) {
  auto update = db_.prepare(
      "UPDATE evaluation_runs SET status = 'failed', finished_utc = ?, error = ?"
      " WHERE status = 'running'");
  update.bind(1, utc_now_iso8601()).bind(2, error);
  update.run();
  return db_.changes();
}

std::optional<RunRecord> EvaluationRunRepository::get(std::int64_t run_id, bool with_samples) {
  auto query = db_.prepare(std::string(kRunSelect) + " WHERE id = ?");
  query.bind(1, run_id);
  if (!query.step()) return std::nullopt;
  RunRecord run = read_run(query);
  auto results =
      db_.prepare(std::string("SELECT r.capture_id, c.label, c.time_utc_s, c.utc_offset_minutes, "
                              "r.sun_zenith_deg, r.sun_azimuth_deg, r.rmse, r.values_compared, "
                              "r.samples_compared, r.out_of_domain, ") +
                  (with_samples ? "e.data" : "NULL") +
                  " FROM evaluation_capture_results r JOIN captures c ON r.capture_id = c.id"
                  " LEFT JOIN evaluation_sample_errors e ON e.id = r.sample_errors_id"
                  " WHERE r.run_id = ? ORDER BY c.time_utc_s, c.label");
  results.bind(1, run_id);
  while (results.step()) {
    RunCaptureResult c;
    c.capture_id = results.column_int64(0);
    c.capture_label = results.column_text(1);
    c.capture_time_utc_s = results.column_double(2);
    c.utc_offset_minutes = static_cast<int>(results.column_int64(3));
    c.sun_zenith_deg = results.column_double(4);
    c.sun_azimuth_deg = results.column_double(5);
    c.answered = !results.is_null(6);
    c.rmse = c.answered ? results.column_double(6) : std::numeric_limits<double>::quiet_NaN();
    c.values_compared = results.column_int64(7);
    c.samples_compared = optional_int(results, 8);
    c.out_of_domain = decode_sample_handling(results.column_text(9));
    if (!results.is_null(10)) c.samples = decode_sample_errors(results.column_blob(10));
    run.captures.push_back(std::move(c));
  }
  return run;
}

std::vector<RunRecord> EvaluationRunRepository::list(std::int64_t dataset_id) {
  auto query = db_.prepare(std::string(kRunSelect) +
                           " WHERE dataset_id = ? ORDER BY started_utc DESC, id DESC");
  query.bind(1, dataset_id);
  std::vector<RunRecord> runs;
  while (query.step()) runs.push_back(read_run(query));
  return runs;
}

KeysetPage<RunRecord> EvaluationRunRepository::list(const RunFilter& filter, std::int64_t limit,
                                                    std::optional<std::int64_t> before_id) {
  // Start times are ISO 8601 UTC text, which julianday() reads (a trailing Z included).
  auto query =
      db_.prepare(std::string(kRunSelect) +
                  " WHERE (?1 IS NULL OR dataset_id = ?1) AND (?2 IS NULL OR model_id = ?2)"
                  " AND (?3 IS NULL OR status = ?3) AND (?4 IS NULL OR job_id = ?4)"
                  " AND (?5 IS NULL OR (julianday(started_utc) - 2440587.5) * 86400.0 >= ?5)"
                  " AND (?6 IS NULL OR (julianday(started_utc) - 2440587.5) * 86400.0 < ?6)"
                  " AND (?7 IS NULL OR id < ?7) ORDER BY id DESC LIMIT ?8");
  const auto bind_id = [&](int index, const std::optional<std::int64_t>& value) {
    if (value)
      query.bind(index, *value);
    else
      query.bind_null(index);
  };
  const auto bind_text = [&](int index, const std::optional<std::string>& value) {
    if (value)
      query.bind(index, *value);
    else
      query.bind_null(index);
  };
  bind_id(1, filter.dataset_id);
  bind_text(2, filter.model_id);
  bind_text(3, filter.status);
  bind_id(4, filter.job_id);
  query.bind_optional(5, filter.since_unix_s);
  query.bind_optional(6, filter.until_unix_s);
  bind_id(7, before_id);
  query.bind(8, limit + 1);
  std::vector<RunRecord> runs;
  while (query.step()) runs.push_back(read_run(query));
  return keyset_page(std::move(runs), limit);
}

std::optional<RunRecord> EvaluationRunRepository::previous_like(const RunRecord& run) {
  auto query = db_.prepare(std::string(kRunSelect) +
                           " WHERE dataset_id = ? AND model_id = ? AND configuration = ?"
                           " AND min_wavelength_nm = ? AND max_wavelength_nm = ?"
                           " AND out_of_domain = ? AND compared_samples IS ?"
                           " AND status = 'succeeded' AND rmse IS NOT NULL AND id < ?"
                           " ORDER BY id DESC LIMIT 1");
  query.bind(1, run.dataset_id)
      .bind(2, run.model_id)
      .bind(3, run.configuration)
      .bind(4, run.min_wavelength_nm)
      .bind(5, run.max_wavelength_nm)
      .bind(6, run.out_of_domain);
  if (run.compared_samples)
    query.bind(7, *run.compared_samples);
  else
    query.bind_null(7);
  query.bind(8, run.id);
  if (!query.step()) return std::nullopt;
  return read_run(query);
}

}  // namespace clearsky::storage
