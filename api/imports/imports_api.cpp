// /v1/imports handlers (imports_api.h).
#include "api/imports/imports_api.h"

#include "api/error/api_error.h"

namespace clearsky::api {
namespace {

nlohmann::ordered_json text_or_null(const std::optional<std::string>& text) {
  if (!text) return nullptr;
  return *text;
}

nlohmann::ordered_json total_or_null(std::int64_t total) {
  if (total < 0) return nullptr;
  return total;
}

}  // namespace

std::string import_location(std::int64_t id) { return "/v1/imports/" + std::to_string(id); }

nlohmann::ordered_json import_to_json(const storage::ImportRecord& record,
                                      const std::optional<storage::ImportProgress>& live) {
  const storage::ImportProgress& p = live && record.status == "running" ? *live : record.progress;
  nlohmann::ordered_json progress = nullptr;
  if (!p.phase.empty() || record.status != "queued")
    progress = {{"phase", p.phase},
                {"bytes_read", p.bytes_read},
                {"bytes_total", total_or_null(p.bytes_total)},
                {"entries_read", p.entries_read},
                {"entries_total", total_or_null(p.entries_total)},
                {"files_read", p.files_read},
                {"captures_added", p.captures_added},
                {"samples_added", p.samples_added}};
  nlohmann::ordered_json report = nullptr;
  if (record.report) report = nlohmann::ordered_json::parse(*record.report);
  nlohmann::ordered_json error = nullptr;
  if (record.error) error = {{"code", record.error_code.value_or("")}, {"message", *record.error}};
  return {
      {"id", record.id},
      {"dataset", record.what.dataset},
      {"format", record.what.format},
      {"source", record.what.source},
      {"path", record.what.source == "path" ? nlohmann::ordered_json(record.what.path)
                                            : nlohmann::ordered_json(nullptr)},
      {"upload_bytes", record.what.upload_bytes ? nlohmann::ordered_json(*record.what.upload_bytes)
                                                : nlohmann::ordered_json(nullptr)},
      {"status", record.status},
      {"progress", std::move(progress)},
      {"timings",
       {{"created", record.created_utc},
        {"started", text_or_null(record.started_utc)},
        {"finished", text_or_null(record.finished_utc)}}},
      {"report", std::move(report)},
      {"error", std::move(error)},
      {"location", import_location(record.id)}};
}

ListPage list_imports(storage::Database& db, const ImportPool* pool, Parameters query) {
  const std::optional<std::string> status = query.text("status");
  if (status && *status != "queued" && *status != "running" && *status != "succeeded" &&
      *status != "failed")
    throw invalid_parameter("status", "one of queued, running, succeeded, failed");
  const std::optional<std::string> dataset = query.text("dataset");
  const PageRequest request = parse_page_request(query);
  query.reject_unused();
  const auto imports = storage::ImportRepository(db).list_page(
      request.limit, status, dataset,
      request.cursor ? std::optional(id_from_cursor(*request.cursor)) : std::nullopt);
  ListPage page;
  page.limit = request.limit;
  for (const storage::ImportRecord& r : imports.rows)
    page.items.push_back(import_to_json(r, pool ? pool->live_progress(r.id) : std::nullopt));
  if (imports.more) page.next_cursor = id_cursor(imports.rows.back().id);
  return page;
}

nlohmann::ordered_json show_import(storage::Database& db, const ImportPool* pool, std::int64_t id) {
  const auto record = storage::ImportRepository(db).get(id);
  if (!record) throw ApiError(404, "unknown_import", "id", "id: no import " + std::to_string(id));
  return import_to_json(*record, pool ? pool->live_progress(id) : std::nullopt);
}

int fail_interrupted_imports(storage::Database& db) {
  return storage::ImportRepository(db).fail_unfinished(
      "interrupted", "interrupted: the server stopped during the import");
}

}  // namespace clearsky::api
