// The database schema as an ordered list of migrations, versioned by PRAGMA user_version:
// migration i brings the schema from version i to i + 1, each in its own transaction, so a
// failed migration leaves the previous version intact. A database newer than this program
// is refused rather than touched.
#pragma once

#include <string_view>
#include <vector>

#include "storage/sqlite/database.h"

namespace clearsky::storage {

// The SQL of each migration, in order (index i: version i -> i + 1).
const std::vector<std::string_view>& schema_migrations();
inline int latest_schema_version() { return static_cast<int>(schema_migrations().size()); }

// Applies the missing migrations; returns the number applied. Throws std::runtime_error when
// the database's version is newer than latest_schema_version().
int migrate(Database& db, const std::vector<std::string_view>& migrations = schema_migrations());

// Opens a database file and brings its schema up to date.
Database open_database(const std::filesystem::path& path, const DatabaseOptions& options = {});

}  // namespace clearsky::storage
