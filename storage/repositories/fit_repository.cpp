// SQL of the fits table (fit_repository.h).
#include "storage/repositories/fit_repository.h"

#include "storage/repositories/utc_clock.h"

namespace clearsky::storage {
namespace {

std::optional<std::string> optional_text(const Statement& row, int column) {
  if (row.is_null(column)) return std::nullopt;
  return row.column_text(column);
}

constexpr const char* kSelect =
    "SELECT f.id, d.name, f.dataset_id, f.model_id, f.model_version, f.free_parameters,"
    " f.fixed_parameters, f.search_options, f.captures, f.settings, f.software_version,"
    " f.status, f.progress, f.stage, f.result, f.rmse_before, f.rmse_search,"
    " f.rmse_after, f.cross_validated_rmse, f.per_capture, f.uncertainty, f.history,"
    " f.timings, f.error, f.created_utc, f.finished_utc"
    " FROM fits f JOIN datasets d ON d.id = f.dataset_id";

FitRecord read_fit(const Statement& row) {
  FitRecord r;
  r.id = row.column_int64(0);
  r.dataset = row.column_text(1);
  r.fit.dataset_id = row.column_int64(2);
  r.fit.model_id = row.column_text(3);
  r.fit.model_version = row.column_text(4);
  r.fit.free_parameters = row.column_text(5);
  r.fit.fixed_parameters = row.column_text(6);
  r.fit.search_options = row.column_text(7);
  r.fit.captures = row.column_text(8);
  r.fit.settings = row.column_text(9);
  r.fit.software_version = row.column_text(10);
  r.fit.status = row.column_text(11);
  r.progress = row.column_double(12);
  r.stage = optional_text(row, 13);
  if (r.fit.status == "succeeded") {
    FitOutcome o;
    o.result = row.column_text(14);
    o.rmse_before = row.column_double_or_nan(15);
    o.rmse_search = row.column_double_or_nan(16);
    o.rmse_after = row.column_double_or_nan(17);
    if (!row.is_null(18)) o.cross_validated_rmse = row.column_double(18);
    o.per_capture = row.column_text(19);
    o.uncertainty = row.column_text(20);
    o.history = row.column_text(21);
    o.timings = row.column_text(22);
    r.outcome = std::move(o);
  }
  r.error = optional_text(row, 23);
  r.created_utc = row.column_text(24);
  r.finished_utc = optional_text(row, 25);
  return r;
}

}  // namespace

std::int64_t FitRepository::start(const NewFit& fit) {
  auto statement = db_.prepare(
      "INSERT INTO fits (dataset_id, model_id, model_version, free_parameters,"
      " fixed_parameters, search_options, captures, settings, software_version, status,"
      " created_utc) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  statement.bind(1, fit.dataset_id)
      .bind(2, fit.model_id)
      .bind(3, fit.model_version)
      .bind(4, fit.free_parameters)
      .bind(5, fit.fixed_parameters)
      .bind(6, fit.search_options)
      .bind(7, fit.captures)
      .bind(8, fit.settings)
      .bind(9, fit.software_version)
      .bind(10, fit.status)
      .bind(11, utc_now_iso8601());
  statement.run();
  return db_.last_insert_rowid();
}

void FitRepository::run(std::int64_t id) {
  auto statement =
      db_.prepare("UPDATE fits SET status = 'running' WHERE id = ? AND status = 'queued'");
  statement.bind(1, id);
  statement.run();
}

void FitRepository::progress(std::int64_t id, double fraction, const std::string& stage) {
  auto statement =
      db_.prepare("UPDATE fits SET progress = ?, stage = ? WHERE id = ? AND status = 'running'");
  statement.bind(1, fraction).bind(2, stage).bind(3, id);
  statement.run();
}

void FitRepository::finish(std::int64_t id, const FitOutcome& outcome) {
  auto statement = db_.prepare(
      "UPDATE fits SET status = 'succeeded', progress = 1, stage = NULL, result = ?,"
      " rmse_before = ?, rmse_search = ?, rmse_after = ?, cross_validated_rmse = ?,"
      " per_capture = ?, uncertainty = ?, history = ?, timings = ?, finished_utc = ?"
      " WHERE id = ?");
  statement.bind(1, outcome.result)
      .bind_optional(2, outcome.rmse_before)
      .bind_optional(3, outcome.rmse_search)
      .bind_optional(4, outcome.rmse_after)
      .bind_optional(5, outcome.cross_validated_rmse)
      .bind(6, outcome.per_capture)
      .bind(7, outcome.uncertainty)
      .bind(8, outcome.history)
      .bind(9, outcome.timings)
      .bind(10, utc_now_iso8601())
      .bind(11, id);
  statement.run();
}

void FitRepository::fail(std::int64_t id, const std::string& error, const std::string& status) {
  auto statement = db_.prepare(
      "UPDATE fits SET status = ?, error = ?, finished_utc = ? WHERE id = ?"
      " AND status IN ('queued', 'running')");
  statement.bind(1, status).bind(2, error).bind(3, utc_now_iso8601()).bind(4, id);
  statement.run();
}

int FitRepository::interrupt_unfinished(const std::string& error) {
  auto statement = db_.prepare(
      "UPDATE fits SET status = 'interrupted', error = ?, finished_utc = ?"
      " WHERE status IN ('queued', 'running')");
  statement.bind(1, error).bind(2, utc_now_iso8601());
  statement.run();
  return db_.changes();
}

std::optional<FitRecord> FitRepository::get(std::int64_t id) {
  auto statement = db_.prepare(std::string(kSelect) + " WHERE f.id = ?");
  statement.bind(1, id);
  if (!statement.step()) return std::nullopt;
  return read_fit(statement);
}

std::vector<FitRecord> FitRepository::list(int limit, std::int64_t before_id) {
  auto statement =
      db_.prepare(std::string(kSelect) + " WHERE (? = 0 OR f.id < ?) ORDER BY f.id DESC LIMIT ?");
  statement.bind(1, before_id).bind(2, before_id).bind(3, limit);
  std::vector<FitRecord> out;
  while (statement.step()) out.push_back(read_fit(statement));
  return out;
}

std::optional<FitRecord> FitRepository::latest_succeeded(const std::string& model_id,
                                                         std::optional<std::int64_t> dataset_id) {
  auto statement = db_.prepare(std::string(kSelect) +
                               " WHERE f.model_id = ? AND f.status = 'succeeded'"
                               " AND (? IS NULL OR f.dataset_id = ?) ORDER BY f.id DESC LIMIT 1");
  statement.bind(1, model_id);
  for (const int index : {2, 3}) {
    if (dataset_id)
      statement.bind(index, *dataset_id);
    else
      statement.bind_null(index);
  }
  if (!statement.step()) return std::nullopt;
  return read_fit(statement);
}

}  // namespace clearsky::storage
