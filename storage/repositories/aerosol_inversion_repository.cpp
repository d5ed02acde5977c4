// SQL of the aerosol_inversions table (aerosol_inversion_repository.h).
#include "storage/repositories/aerosol_inversion_repository.h"

#include <cstddef>
#include <span>

#include "storage/repositories/utc_clock.h"

namespace clearsky::storage {
namespace {

constexpr const char* kSelect =
    "SELECT id, name, content_hash, site, latitude_deg, longitude_deg, first_day, last_day,"
    " retrieval_count, size_bytes, created_utc FROM aerosol_inversions";

AerosolInversionSummary read_summary(const Statement& row) {
  AerosolInversionSummary s;
  s.id = row.column_int64(0);
  s.inversion.name = row.column_text(1);
  s.inversion.content_hash = row.column_text(2);
  s.inversion.site = row.column_text(3);
  s.inversion.latitude_deg = row.column_double(4);
  s.inversion.longitude_deg = row.column_double(5);
  s.inversion.first_day = row.column_text(6);
  s.inversion.last_day = row.column_text(7);
  s.inversion.retrieval_count = row.column_int64(8);
  s.size_bytes = row.column_int64(9);
  s.created_utc = row.column_text(10);
  return s;
}

}  // namespace

std::int64_t AerosolInversionRepository::create(const NewAerosolInversion& inversion,
                                                std::string_view content) {
  auto statement = db_.prepare(
      "INSERT INTO aerosol_inversions (name, content_hash, site, latitude_deg, longitude_deg,"
      " first_day, last_day, retrieval_count, size_bytes, content, created_utc)"
      " VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  statement.bind(1, inversion.name)
      .bind(2, inversion.content_hash)
      .bind(3, inversion.site)
      .bind(4, inversion.latitude_deg)
      .bind(5, inversion.longitude_deg)
      .bind(6, inversion.first_day)
      .bind(7, inversion.last_day)
      .bind(8, inversion.retrieval_count)
      .bind(9, static_cast<std::int64_t>(content.size()))
      .bind_blob(10, std::as_bytes(std::span(content.data(), content.size())))
      .bind(11, utc_now_iso8601());
  statement.run();
  return db_.last_insert_rowid();
}

std::optional<AerosolInversionSummary> AerosolInversionRepository::find(std::int64_t id) {
  auto statement = db_.prepare(std::string(kSelect) + " WHERE id = ?");
  statement.bind(1, id);
  if (!statement.step()) return std::nullopt;
  return read_summary(statement);
}

std::optional<std::string> AerosolInversionRepository::content(std::int64_t id) {
  auto statement = db_.prepare("SELECT content FROM aerosol_inversions WHERE id = ?");
  statement.bind(1, id);
  if (!statement.step()) return std::nullopt;
  const std::vector<std::byte> bytes = statement.column_blob(0);
  return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

KeysetPage<AerosolInversionSummary> AerosolInversionRepository::list_page(std::int64_t limit,
                                                                          std::int64_t before_id) {
  auto statement =
      db_.prepare(std::string(kSelect) + " WHERE (? = 0 OR id < ?) ORDER BY id DESC LIMIT ?");
  statement.bind(1, before_id).bind(2, before_id).bind(3, limit + 1);
  std::vector<AerosolInversionSummary> rows;
  while (statement.step()) rows.push_back(read_summary(statement));
  return keyset_page(std::move(rows), limit);
}

}  // namespace clearsky::storage
