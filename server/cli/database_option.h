// The --db option every data command takes (docs/architecture.md "Command line"), and opening the
// database it names (parent folder created, schema migrated).
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <string>

#include "storage/schema/migrations.h"

namespace clearsky::cli {

inline void add_database_option(CLI::App& command, std::string& path) {
  command.add_option("--db", path, "SQLite database file")->capture_default_str();
}

inline storage::Database open_cli_database(const std::string& path) {
  const std::filesystem::path file(path);
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  return storage::open_database(file);
}

constexpr const char* kDefaultDatabasePath = "var/clearsky.db";

}  // namespace clearsky::cli
