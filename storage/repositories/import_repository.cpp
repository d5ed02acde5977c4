// SQL of the imports table (import_repository.h).
#include "storage/repositories/import_repository.h"

#include "storage/repositories/utc_clock.h"

namespace clearsky::storage {
namespace {

constexpr const char* kImportSelect =
    "SELECT id, dataset, format, source, path, upload_bytes, status, created_utc, started_utc,"
    " finished_utc, phase, bytes_read, bytes_total, entries_read, entries_total, files_read,"
    " captures_added, samples_added, report, error_code, error FROM imports";

std::optional<std::string> optional_text(const Statement& row, int column) {
  if (row.is_null(column)) return std::nullopt;
  return row.column_text(column);
}

std::int64_t int_or(const Statement& row, int column, std::int64_t absent) {
  return row.is_null(column) ? absent : row.column_int64(column);
}

ImportRecord read_import(const Statement& row) {
  ImportRecord r;
  r.id = row.column_int64(0);
  r.what.dataset = row.column_text(1);
  r.what.format = row.column_text(2);
  r.what.source = row.column_text(3);
  r.what.path = row.column_text(4);
  if (!row.is_null(5)) r.what.upload_bytes = row.column_int64(5);
  r.status = row.column_text(6);
  r.created_utc = row.column_text(7);
  r.started_utc = optional_text(row, 8);
  r.finished_utc = optional_text(row, 9);
  r.progress.phase = row.column_text(10);
  r.progress.bytes_read = row.column_int64(11);
  r.progress.bytes_total = int_or(row, 12, -1);
  r.progress.entries_read = row.column_int64(13);
  r.progress.entries_total = int_or(row, 14, -1);
  r.progress.files_read = row.column_int64(15);
  r.progress.captures_added = row.column_int64(16);
  r.progress.samples_added = row.column_int64(17);
  r.report = optional_text(row, 18);
  r.error_code = optional_text(row, 19);
  r.error = optional_text(row, 20);
  return r;
}

// Binds a count that is -1 when unknown.
void bind_total(Statement& statement, int index, std::int64_t total) {
  if (total < 0)
    statement.bind_null(index);
  else
    statement.bind(index, total);
}

void finish(Database& db, std::int64_t id, const std::string& status,
            const ImportProgress& progress, const std::optional<std::string>& report,
            const std::optional<std::string>& error_code, const std::optional<std::string>& error) {
  auto statement = db.prepare(
      "UPDATE imports SET status = ?, finished_utc = ?, phase = ?, bytes_read = ?,"
      " bytes_total = ?, entries_read = ?, entries_total = ?, files_read = ?,"
      " captures_added = ?, samples_added = ?, report = ?, error_code = ?, error = ?"
      " WHERE id = ?");
  statement.bind(1, status)
      .bind(2, utc_now_iso8601())
      .bind(3, progress.phase)
      .bind(4, progress.bytes_read);
  bind_total(statement, 5, progress.bytes_total);
  statement.bind(6, progress.entries_read);
  bind_total(statement, 7, progress.entries_total);
  statement.bind(8, progress.files_read)
      .bind(9, progress.captures_added)
      .bind(10, progress.samples_added);
  for (const auto& [index, text] : {std::pair{11, &report}, {12, &error_code}, {13, &error}}) {
    if (*text)
      statement.bind(index, **text);
    else
      statement.bind_null(index);
  }
  statement.bind(14, id);
  statement.run();
}

}  // namespace

std::int64_t ImportRepository::create(const NewImport& import) {
  auto statement = db_.prepare(
      "INSERT INTO imports (dataset, format, source, path, upload_bytes, status, created_utc)"
      " VALUES (?, ?, ?, ?, ?, 'queued', ?)");
  statement.bind(1, import.dataset)
      .bind(2, import.format)
      .bind(3, import.source)
      .bind(4, import.path);
  if (import.upload_bytes)
    statement.bind(5, *import.upload_bytes);
  else
    statement.bind_null(5);
  statement.bind(6, utc_now_iso8601());
  statement.run();
  return db_.last_insert_rowid();
}

void ImportRepository::start(std::int64_t id) {
  auto statement = db_.prepare(
      "UPDATE imports SET status = 'running', started_utc = ?, phase = 'reading' WHERE id = ?");
  statement.bind(1, utc_now_iso8601()).bind(2, id);
  statement.run();
}

void ImportRepository::succeed(std::int64_t id, const ImportProgress& progress,
                               const std::string& report_json) {
  finish(db_, id, "succeeded", progress, report_json, std::nullopt, std::nullopt);
}

void ImportRepository::fail(std::int64_t id, const ImportProgress& progress,
                            const std::string& error_code, const std::string& error) {
  finish(db_, id, "failed", progress, std::nullopt, error_code, error);
}

int ImportRepository::fail_unfinished(const std::string& error_code, const std::string& error) {
  auto statement = db_.prepare(
      "UPDATE imports SET status = 'failed', finished_utc = ?, error_code = ?, error = ?"
      " WHERE status IN ('queued', 'running')");
  statement.bind(1, utc_now_iso8601()).bind(2, error_code).bind(3, error);
  statement.run();
  return db_.changes();
}

std::optional<ImportRecord> ImportRepository::get(std::int64_t id) {
  auto statement = db_.prepare(std::string(kImportSelect) + " WHERE id = ?");
  statement.bind(1, id);
  if (!statement.step()) return std::nullopt;
  return read_import(statement);
}

std::vector<ImportRecord> ImportRepository::list(std::int64_t limit,
                                                 const std::optional<std::string>& status,
                                                 const std::optional<std::string>& dataset) {
  return list_page(limit, status, dataset, std::nullopt).rows;
}

KeysetPage<ImportRecord> ImportRepository::list_page(std::int64_t limit,
                                                     const std::optional<std::string>& status,
                                                     const std::optional<std::string>& dataset,
                                                     std::optional<std::int64_t> before_id) {
  auto statement = db_.prepare(std::string(kImportSelect) +
                               " WHERE (?1 IS NULL OR status = ?1) AND (?2 IS NULL OR dataset = ?2)"
                               " AND (?3 IS NULL OR id < ?3) ORDER BY id DESC LIMIT ?4");
  if (status)
    statement.bind(1, *status);
  else
    statement.bind_null(1);
  if (dataset)
    statement.bind(2, *dataset);
  else
    statement.bind_null(2);
  if (before_id)
    statement.bind(3, *before_id);
  else
    statement.bind_null(3);
  statement.bind(4, limit + 1);
  std::vector<ImportRecord> out;
  while (statement.step()) out.push_back(read_import(statement));
  return keyset_page(std::move(out), limit);
}

}  // namespace clearsky::storage
