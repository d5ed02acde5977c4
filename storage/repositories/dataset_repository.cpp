// SQL of the datasets table (dataset_repository.h).
#include "storage/repositories/dataset_repository.h"

#include <stdexcept>

#include "storage/importers/import_conflict.h"
#include "storage/repositories/utc_clock.h"

namespace clearsky::storage {
namespace {

constexpr const char* kSummarySelect =
    "SELECT d.id, d.name, d.format, d.created_utc,"
    " (SELECT COUNT(*) FROM captures c WHERE c.dataset_id = d.id),"
    " (SELECT COUNT(*) FROM samples s JOIN captures c ON s.capture_id = c.id WHERE c.dataset_id = "
    "d.id),"
    " d.kind, (SELECT COUNT(*) FROM irradiance_samples i WHERE i.dataset_id = d.id)"
    " FROM datasets d";

DatasetSummary read_summary(const Statement& row) {
  return {row.column_int64(0), row.column_text(1),  row.column_text(2), row.column_text(3),
          row.column_int64(4), row.column_int64(5), row.column_text(6), row.column_int64(7)};
}

}  // namespace

std::int64_t DatasetRepository::find_or_create(const std::string& name, const std::string& format,
                                               std::string_view kind) {
  if (name.empty()) throw std::invalid_argument("dataset name must not be empty");
  // A format belongs to one kind (kider2014 and the sky-radiance format to sky_radiance, the
  // irradiance formats to broadband_irradiance), so the format's check covers the kind's.
  auto query = db_.prepare("SELECT id, format FROM datasets WHERE name = ?");
  query.bind(1, name);
  if (query.step()) {
    if (query.column_text(1) != format)
      throw ImportConflict("dataset '" + name + "' exists with format " + query.column_text(1) +
                           ", not " + format);
    return query.column_int64(0);
  }
  // A sky-radiance dataset takes the column's default, so that this also writes the databases
  // of versions before 9 that the migration tests build.
  auto insert = db_.prepare(
      kind == kSkyRadianceKind ? "INSERT INTO datasets (name, format, created_utc) VALUES (?, ?, ?)"
                               : "INSERT INTO datasets (name, format, created_utc, kind)"
                                 " VALUES (?, ?, ?, ?)");
  insert.bind(1, name).bind(2, format).bind(3, utc_now_iso8601());
  if (kind != kSkyRadianceKind) insert.bind(4, kind);
  insert.run();
  return db_.last_insert_rowid();
}

std::optional<DatasetSummary> DatasetRepository::find(const std::string& name) {
  auto query = db_.prepare(std::string(kSummarySelect) + " WHERE d.name = ?");
  query.bind(1, name);
  if (!query.step()) return std::nullopt;
  return read_summary(query);
}

std::vector<DatasetSummary> DatasetRepository::list() {
  auto query = db_.prepare(std::string(kSummarySelect) + " ORDER BY d.name");
  std::vector<DatasetSummary> result;
  while (query.step()) result.push_back(read_summary(query));
  return result;
}

KeysetPage<DatasetSummary> DatasetRepository::list_page(
    std::int64_t limit, const std::optional<std::string>& after_name) {
  auto query = db_.prepare(std::string(kSummarySelect) +
                           " WHERE ?1 IS NULL OR d.name > ?1 ORDER BY d.name LIMIT ?2");
  if (after_name)
    query.bind(1, *after_name);
  else
    query.bind_null(1);
  query.bind(2, limit + 1);
  std::vector<DatasetSummary> result;
  while (query.step()) result.push_back(read_summary(query));
  return keyset_page(std::move(result), limit);
}

bool DatasetRepository::remove(const std::string& name) {
  auto statement = db_.prepare("DELETE FROM datasets WHERE name = ?");
  statement.bind(1, name);
  statement.run();
  return db_.changes() > 0;
}

}  // namespace clearsky::storage
