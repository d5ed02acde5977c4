// /v1/imports, transport-free: the state of dataset imports (docs/data-api.md "Imports"), stored rows
// (storage/repositories/import_repository.h) with the live progress of those running in the
// server's ImportPool. JSON of one import:
//   {"id", "dataset", "format", "source": "upload"|"path", "path" (or null),
//    "upload_bytes" (or null), "status": queued|running|succeeded|failed,
//    "progress": {"phase": reading|writing|committed, "bytes_read", "bytes_total",
//                 "entries_read", "entries_total", "files_read", "captures_added",
//                 "samples_added"} (totals null while unknown),
//    "timings": {"created", "started", "finished"} (ISO 8601 UTC or null),
//    "report": the import report of api/datasets/datasets_api.h on success (else null),
//    "error": {"code", "message"} on failure (else null), "location": "/v1/imports/{id}"}
// An import a crash interrupted reads failed with code "interrupted" after the restart.
// Thread-safety: each call uses the given Database from the calling thread only.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "api/imports/import_pool.h"
#include "api/paging/list_page.h"
#include "api/request/parameters.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

// The path of an import's state.
std::string import_location(std::int64_t id);

nlohmann::ordered_json import_to_json(const storage::ImportRecord& record,
                                      const std::optional<storage::ImportProgress>& live = {});

// Newest (highest id) first, paged (limit, cursor: api/paging/list_page.h); filters status and
// dataset from the query, applied before the limit (400 for other parameters). pool may be
// null (no live progress).
ListPage list_imports(storage::Database& db, const ImportPool* pool, Parameters query);
// 404 unknown_import when absent.
nlohmann::ordered_json show_import(storage::Database& db, const ImportPool* pool, std::int64_t id);

// What start-up records for imports a crash left queued or running; returns how many.
int fail_interrupted_imports(storage::Database& db);

}  // namespace clearsky::api
