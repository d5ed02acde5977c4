// Dataset imports as rows of the imports table: what is imported (dataset, format,
// an upload or a server-side path), its state (queued, running, succeeded, failed), timings,
// the last progress recorded, the report (JSON text) on success and the error on failure.
// An import is recorded before it is queued so that a crash leaves a trace, which start-up
// turns into a failure (fail_unfinished). Ids are never reused (schema version 4). SQL on this
// table lives only here.
// Thread-safety: as the Database it uses.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "storage/importers/kider_importer.h"
#include "storage/repositories/keyset_page.h"
#include "storage/sqlite/database.h"

namespace clearsky::storage {

struct NewImport {
  std::string dataset;
  std::string format;
  std::string source;  // "upload" or "path"
  std::string path;    // the server-side path (source "path")
  std::optional<std::int64_t> upload_bytes;
};

struct ImportRecord {
  std::int64_t id = 0;
  NewImport what;
  std::string status;  // queued, running, succeeded, failed
  std::string created_utc;
  std::optional<std::string> started_utc, finished_utc;
  ImportProgress progress;            // phase empty while queued
  std::optional<std::string> report;  // JSON
  std::optional<std::string> error_code, error;
};

class ImportRepository {
 public:
  explicit ImportRepository(Database& db) : db_(db) {}
  // A queued import; returns its id.
  std::int64_t create(const NewImport& import);
  void start(std::int64_t id);
  void succeed(std::int64_t id, const ImportProgress& progress, const std::string& report_json);
  void fail(std::int64_t id, const ImportProgress& progress, const std::string& error_code,
            const std::string& error);
  // Marks every import still queued or running as failed (at start-up: a crash interrupted
  // them and their spool files are gone); returns how many.
  int fail_unfinished(const std::string& error_code, const std::string& error);
  std::optional<ImportRecord> get(std::int64_t id);
  // Newest first; at most limit rows; only those with the given status and dataset when set.
  std::vector<ImportRecord> list(std::int64_t limit = 100,
                                 const std::optional<std::string>& status = {},
                                 const std::optional<std::string>& dataset = {});
  // The same as a keyset page: ids below before_id when given.
  KeysetPage<ImportRecord> list_page(std::int64_t limit, const std::optional<std::string>& status,
                                     const std::optional<std::string>& dataset,
                                     std::optional<std::int64_t> before_id);

 private:
  Database& db_;
};

}  // namespace clearsky::storage
