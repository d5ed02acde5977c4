// An in-memory database migrated to an earlier schema version (the first `version` migrations of
// storage/schema/migrations.cpp), so that a schema test can write rows as that version stored
// them and then check what the next migration does with them.
#pragma once

#include <string_view>
#include <vector>

#include "storage/schema/migrations.h"

namespace clearsky::testing {

inline storage::Database database_at_schema_version(int version) {
  storage::Database db = storage::Database::open(":memory:");
  const auto& all = storage::schema_migrations();
  storage::migrate(db, std::vector<std::string_view>(all.begin(), all.begin() + version));
  return db;
}

}  // namespace clearsky::testing
