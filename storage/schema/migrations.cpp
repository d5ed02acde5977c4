// Schema migrations (migrations.h). Tables (docs/architecture.md "Storage and durability"):
// datasets of measured captures, their samples (spectra as float64 blobs), evaluation runs with
// per-capture results, and scheduled evaluation jobs; dataset imports. Times are ISO 8601 UTC text
// except capture instants (unix seconds).
#include "storage/schema/migrations.h"

#include <string>

namespace clearsky::storage {

const std::vector<std::string_view>& schema_migrations() {
  static const std::vector<std::string_view> migrations = {
      // Version 1.
      R"sql(
CREATE TABLE datasets (
  id INTEGER PRIMARY KEY,
  name TEXT NOT NULL UNIQUE,
  format TEXT NOT NULL,
  created_utc TEXT NOT NULL
);
CREATE TABLE captures (
  id INTEGER PRIMARY KEY,
  dataset_id INTEGER NOT NULL REFERENCES datasets(id) ON DELETE CASCADE,
  label TEXT NOT NULL,
  time_utc_s REAL NOT NULL,
  utc_offset_minutes INTEGER NOT NULL,
  latitude_deg REAL NOT NULL,
  longitude_deg REAL NOT NULL,
  elevation_m REAL NOT NULL,
  sun_zenith_computed_deg REAL,
  sun_azimuth_computed_deg REAL,
  sun_azimuth_estimated_deg REAL,
  content_hash TEXT NOT NULL,
  source TEXT NOT NULL,
  imported_utc TEXT NOT NULL,
  UNIQUE (dataset_id, label),
  UNIQUE (dataset_id, content_hash)
);
CREATE TABLE samples (
  id INTEGER PRIMARY KEY,
  capture_id INTEGER NOT NULL REFERENCES captures(id) ON DELETE CASCADE,
  scan_index INTEGER NOT NULL,
  view_zenith_rad REAL NOT NULL,
  view_azimuth_rad REAL NOT NULL,
  wavelengths_nm BLOB NOT NULL,
  radiance BLOB NOT NULL,
  quality_flags INTEGER NOT NULL DEFAULT 0,
  UNIQUE (capture_id, scan_index)
);
CREATE TABLE jobs (
  id INTEGER PRIMARY KEY,
  name TEXT NOT NULL UNIQUE,
  schedule TEXT NOT NULL,
  dataset_id INTEGER NOT NULL REFERENCES datasets(id) ON DELETE CASCADE,
  models TEXT NOT NULL,
  parameters TEXT NOT NULL DEFAULT '',
  paused INTEGER NOT NULL DEFAULT 0 CHECK (paused IN (0, 1)),
  created_utc TEXT NOT NULL,
  last_run_utc TEXT,
  next_run_utc TEXT
);
CREATE TABLE evaluation_runs (
  id INTEGER PRIMARY KEY,
  dataset_id INTEGER NOT NULL REFERENCES datasets(id) ON DELETE CASCADE,
  job_id INTEGER REFERENCES jobs(id) ON DELETE SET NULL,
  model_id TEXT NOT NULL,
  model_version TEXT NOT NULL,
  parameters TEXT NOT NULL,
  software_version TEXT NOT NULL,
  min_wavelength_nm REAL NOT NULL,
  max_wavelength_nm REAL NOT NULL,
  started_utc TEXT NOT NULL,
  finished_utc TEXT,
  status TEXT NOT NULL CHECK (status IN ('running', 'succeeded', 'failed')),
  error TEXT,
  rmse REAL,
  precompute_seconds REAL,
  evaluate_seconds REAL,
  processing_steps TEXT NOT NULL DEFAULT ''
);
CREATE TABLE evaluation_capture_results (
  run_id INTEGER NOT NULL REFERENCES evaluation_runs(id) ON DELETE CASCADE,
  capture_id INTEGER NOT NULL REFERENCES captures(id) ON DELETE CASCADE,
  sun_zenith_deg REAL NOT NULL,
  sun_azimuth_deg REAL NOT NULL,
  rmse REAL NOT NULL,
  values_compared INTEGER NOT NULL,
  PRIMARY KEY (run_id, capture_id)
);
CREATE INDEX captures_by_dataset ON captures(dataset_id, time_utc_s);
CREATE INDEX samples_by_capture ON samples(capture_id, scan_index);
CREATE INDEX runs_by_dataset ON evaluation_runs(dataset_id, started_utc);
)sql",
      // Version 2: per-sample errors of evaluation runs. A run lists its compared wavelengths
      // once (float64 blob); each capture result may point to a blob of its samples' errors
      // (storage/repositories/sample_errors_blob.h). Identical blobs are stored once (a
      // scheduled job re-evaluating the same model on the same captures gets the same errors
      // bit for bit), found by their FNV-1a 64 hash and compared byte for byte; a blob goes
      // with its last reference. Runs before version 2 have neither: their samples are unknown.
      R"sql(
ALTER TABLE evaluation_runs ADD COLUMN wavelengths_nm BLOB;
CREATE TABLE evaluation_sample_errors (
  id INTEGER PRIMARY KEY,
  content_hash INTEGER NOT NULL,
  data BLOB NOT NULL
);
CREATE INDEX sample_errors_by_hash ON evaluation_sample_errors(content_hash);
ALTER TABLE evaluation_capture_results
  ADD COLUMN sample_errors_id INTEGER REFERENCES evaluation_sample_errors(id);
CREATE INDEX capture_results_by_sample_errors ON evaluation_capture_results(sample_errors_id);
CREATE TRIGGER sample_errors_follow_their_last_reference
AFTER DELETE ON evaluation_capture_results
WHEN OLD.sample_errors_id IS NOT NULL
BEGIN
  DELETE FROM evaluation_sample_errors WHERE id = OLD.sample_errors_id AND NOT EXISTS (
    SELECT 1 FROM evaluation_capture_results WHERE sample_errors_id = OLD.sample_errors_id);
END;
)sql",
      // Version 3: dataset imports run as background jobs. A row per import, kept
      // after its dataset is deleted (no foreign key); progress columns hold the last known
      // counts (the live ones are in the server's memory while it runs).
      R"sql(
CREATE TABLE imports (
  id INTEGER PRIMARY KEY,
  dataset TEXT NOT NULL,
  format TEXT NOT NULL,
  source TEXT NOT NULL CHECK (source IN ('upload', 'path')),
  path TEXT NOT NULL DEFAULT '',
  upload_bytes INTEGER,
  status TEXT NOT NULL CHECK (status IN ('queued', 'running', 'succeeded', 'failed')),
  created_utc TEXT NOT NULL,
  started_utc TEXT,
  finished_utc TEXT,
  phase TEXT NOT NULL DEFAULT '',
  bytes_read INTEGER NOT NULL DEFAULT 0,
  bytes_total INTEGER,
  entries_read INTEGER NOT NULL DEFAULT 0,
  entries_total INTEGER,
  files_read INTEGER NOT NULL DEFAULT 0,
  captures_added INTEGER NOT NULL DEFAULT 0,
  samples_added INTEGER NOT NULL DEFAULT 0,
  report TEXT,
  error_code TEXT,
  error TEXT
);
CREATE INDEX imports_by_status ON imports(status);
)sql",
  };
  return migrations;
}

int migrate(Database& db, const std::vector<std::string_view>& migrations) {
  const int latest = static_cast<int>(migrations.size());
  int applied = 0;
  for (;;) {
    Transaction transaction(db);
    // Read inside the write transaction: two processes migrating at once apply each step once.
    const int version = db.user_version();
    if (version > latest)
      throw std::runtime_error("database schema version " + std::to_string(version) +
                               " is newer than this program's " + std::to_string(latest));
    if (version == latest) {
      transaction.commit();
      return applied;
    }
    db.execute(migrations[static_cast<std::size_t>(version)]);
    db.execute("PRAGMA user_version = " + std::to_string(version + 1));
    transaction.commit();
    ++applied;
  }
}

Database open_database(const std::filesystem::path& path, const DatabaseOptions& options) {
  Database db = Database::open(path, options);
  if (!options.read_only) migrate(db);
  return db;
}

}  // namespace clearsky::storage
