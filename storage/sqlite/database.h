// SQLite through RAII (docs/conventions.md "Resources and transactions"): a Database owns one
// connection, a Statement one prepared statement, a Transaction rolls back unless committed.
// Destructors never throw. Errors are SqliteError carrying SQLite's result code and message.
// Connections open with WAL journaling (files), foreign keys on and a busy timeout, so that several
// processes (server, CLI) can share one file.
// Thread-safety: a Database and its Statements belong to one thread at a time; open one
// connection per thread (SQLite's serialized mode is not relied upon).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

struct sqlite3;
struct sqlite3_stmt;

namespace clearsky::storage {

class SqliteError : public std::runtime_error {
 public:
  SqliteError(int code, const std::string& message);
  int code() const { return code_; }
  // SQLITE_FULL: the disk (or the database's page limit) is full.
  bool disk_full() const;

 private:
  int code_;
};

class Statement;

struct DatabaseOptions {
  int busy_timeout_ms = 5000;
  bool read_only = false;
};

class Database {
 public:
  // Opens (creating if needed) a database file, or ":memory:". Throws SqliteError.
  static Database open(const std::filesystem::path& path, const DatabaseOptions& options = {});

  Database(Database&& other) noexcept;
  Database& operator=(Database&& other) noexcept;
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;
  ~Database();

  // Runs one or more SQL statements without results.
  void execute(std::string_view sql);
  Statement prepare(std::string_view sql);
  std::int64_t last_insert_rowid() const;
  int changes() const;
  // PRAGMA user_version.
  int user_version();
  sqlite3* handle() const { return db_; }

 private:
  explicit Database(sqlite3* db) : db_(db) {}
  sqlite3* db_ = nullptr;
};

// Blobs are bound and read as bytes; arrays of doubles are stored little-endian (blob.h).
class Statement {
 public:
  Statement(Statement&& other) noexcept;
  Statement& operator=(Statement&& other) noexcept;
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  ~Statement();

  // Parameters are numbered from 1, as in SQLite.
  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, int value) { return bind(index, static_cast<std::int64_t>(value)); }
  Statement& bind(int index, double value);
  Statement& bind(int index, std::string_view text);
  Statement& bind(int index, const char* text) { return bind(index, std::string_view(text)); }
  Statement& bind(int index, const std::string& text) {
    return bind(index, std::string_view(text));
  }
  Statement& bind_blob(int index, std::span<const std::byte> bytes);
  Statement& bind_null(int index);
  // A NaN or an empty optional binds NULL.
  Statement& bind_optional(int index, std::optional<double> value);

  // Advances to the next row: true when a row is available, false when done.
  bool step();
  // Runs a statement that returns no rows (throws if it returns one).
  void run();
  void reset();

  // Columns are numbered from 0.
  bool is_null(int column) const;
  std::int64_t column_int64(int column) const;
  double column_double(int column) const;
  // NaN for NULL.
  double column_double_or_nan(int column) const;
  std::string column_text(int column) const;
  std::vector<std::byte> column_blob(int column) const;

 private:
  friend class Database;
  Statement(sqlite3* db, sqlite3_stmt* statement) : db_(db), statement_(statement) {}
  void check(int code, const char* what) const;
  sqlite3* db_ = nullptr;
  sqlite3_stmt* statement_ = nullptr;
};

// BEGIN IMMEDIATE on construction (the write lock is taken at once, so a busy database fails
// here rather than half-way); ROLLBACK in the destructor unless commit() succeeded.
class Transaction {
 public:
  explicit Transaction(Database& db);
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  ~Transaction();
  void commit();

 private:
  Database& db_;
  bool done_ = false;
};

}  // namespace clearsky::storage
