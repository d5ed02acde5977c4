// Users' AERONET phase-function inversions as rows of the aerosol_inversions table
// (storage/schema/migrations.cpp; docs/data-api.md "Aerosol inversions"): the uploaded file's
// bytes and what the reader of models/aeronet found in it. The storage layer does not parse the
// file: the api layer validates it before create() and parses the bytes get_content() returns.
// SQL on this table lives only here. Ids are never reused (AUTOINCREMENT).
// Thread-safety: as the Database it uses.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/repositories/keyset_page.h"
#include "storage/sqlite/database.h"

namespace clearsky::storage {

struct NewAerosolInversion {
  std::string name;          // the uploader's label
  std::string content_hash;  // 16 hex digits, FNV-1a 64 of the bytes (models/core/content_hash.h)
  std::string site;          // Locations= of the file
  double latitude_deg = 0;
  double longitude_deg = 0;
  std::string first_day;  // ISO 8601 yyyy-mm-dd of the first retrieval
  std::string last_day;   // and of the last
  std::int64_t retrieval_count = 0;
};

struct AerosolInversionSummary {
  std::int64_t id = 0;
  NewAerosolInversion inversion;
  std::int64_t size_bytes = 0;
  std::string created_utc;
};

class AerosolInversionRepository {
 public:
  explicit AerosolInversionRepository(Database& db) : db_(db) {}
  // Stores the file's bytes with their description; returns the new id.
  std::int64_t create(const NewAerosolInversion& inversion, std::string_view content);
  std::optional<AerosolInversionSummary> find(std::int64_t id);
  // The file's bytes as uploaded; nullopt when there is no such id.
  std::optional<std::string> content(std::int64_t id);
  // Newest first: at most limit inversions with id < before_id (0: from the newest).
  KeysetPage<AerosolInversionSummary> list_page(std::int64_t limit, std::int64_t before_id = 0);

 private:
  Database& db_;
};

}  // namespace clearsky::storage
