// Schema migrations (migrations.h). Tables (docs/architecture.md "Storage and durability"):
// datasets of measured captures, their samples (spectra as float64 blobs), evaluation runs with
// per-capture results, and scheduled evaluation jobs; dataset imports; from version 4, ids never
// reused and run parameters as JSON (docs/data-api.md); from version 7, atmosphere fits
// (docs/fits.md); from version 9, users' aerosol inversions; from version 10, datasets of
// broadband irradiance time series; from version 11, jobs that re-fit their dataset. Times are
// ISO 8601 UTC text except capture and irradiance sample instants (unix seconds).
#include "storage/schema/migrations.h"

#include <string>

#include "storage/repositories/compared_samples.h"
#include "storage/schema/legacy_run_parameters.h"

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
      // Version 4 (docs/data-api.md "Ids" and "Evaluation parameters"):
      // - ids are never reused: jobs, evaluation runs and imports get AUTOINCREMENT (a table
      //   can only get it by being rebuilt, which migrate() does with foreign keys off);
      // - a run keeps its job id after the job is deleted (no foreign key on job_id), so that
      //   GET /v1/evaluations?job=N still finds it;
      // - a run's parameters are a JSON object of the parameters applied to its model, as the
      //   user gave them; the model's full configuration key (ModelConfig::canonical_string(),
      //   what the column held before) moves to `configuration`, which the history comparison
      //   uses. Existing rows are converted by legacy_run_parameters_json
      //   (legacy_run_parameters.h).
      R"sql(
CREATE TABLE jobs_v4 (
  id INTEGER PRIMARY KEY AUTOINCREMENT,
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
INSERT INTO jobs_v4 (id, name, schedule, dataset_id, models, parameters, paused, created_utc,
                     last_run_utc, next_run_utc)
  SELECT id, name, schedule, dataset_id, models, parameters, paused, created_utc, last_run_utc,
         next_run_utc FROM jobs;
DROP TABLE jobs;
ALTER TABLE jobs_v4 RENAME TO jobs;

CREATE TABLE evaluation_runs_v4 (
  id INTEGER PRIMARY KEY AUTOINCREMENT,
  dataset_id INTEGER NOT NULL REFERENCES datasets(id) ON DELETE CASCADE,
  job_id INTEGER,
  model_id TEXT NOT NULL,
  model_version TEXT NOT NULL,
  parameters TEXT NOT NULL DEFAULT '{}',
  configuration TEXT NOT NULL,
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
  processing_steps TEXT NOT NULL DEFAULT '',
  wavelengths_nm BLOB
);
INSERT INTO evaluation_runs_v4 (id, dataset_id, job_id, model_id, model_version, parameters,
                                configuration, software_version, min_wavelength_nm,
                                max_wavelength_nm, started_utc, finished_utc, status, error, rmse,
                                precompute_seconds, evaluate_seconds, processing_steps,
                                wavelengths_nm)
  SELECT id, dataset_id, job_id, model_id, model_version, legacy_run_parameters_json(parameters),
         parameters, software_version, min_wavelength_nm, max_wavelength_nm, started_utc,
         finished_utc, status, error, rmse, precompute_seconds, evaluate_seconds,
         processing_steps, wavelengths_nm FROM evaluation_runs;
DROP TABLE evaluation_runs;
ALTER TABLE evaluation_runs_v4 RENAME TO evaluation_runs;
CREATE INDEX runs_by_dataset ON evaluation_runs(dataset_id, started_utc);
CREATE INDEX runs_by_job ON evaluation_runs(job_id);

CREATE TABLE imports_v4 (
  id INTEGER PRIMARY KEY AUTOINCREMENT,
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
INSERT INTO imports_v4 SELECT * FROM imports;
DROP TABLE imports;
ALTER TABLE imports_v4 RENAME TO imports;
CREATE INDEX imports_by_status ON imports(status);
)sql",
      // Version 5 (docs/data-api.md "Evaluations"): samples a model cannot answer are left out
      // (or clamped) and counted instead of failing the run.
      // - a capture result's rmse may be NULL (a capture of which the model answered no sample;
      //   the table is rebuilt to drop NOT NULL), with the samples it compared and the
      //   samples it left out or clamped (storage/repositories/compared_samples.h);
      // - a run records its out-of-domain handling, the samples its RMSE covers, how many it
      //   left out or clamped, its unanswered captures, and the key of its compared samples
      //   that the history comparison matches. Runs stored before compared every sample of
      //   their captures (they failed otherwise): their counts come from values_compared and
      //   their key from their captures' labels.
      R"sql(
CREATE TABLE evaluation_capture_results_v5 (
  run_id INTEGER NOT NULL REFERENCES evaluation_runs(id) ON DELETE CASCADE,
  capture_id INTEGER NOT NULL REFERENCES captures(id) ON DELETE CASCADE,
  sun_zenith_deg REAL NOT NULL,
  sun_azimuth_deg REAL NOT NULL,
  rmse REAL,
  values_compared INTEGER NOT NULL,
  sample_errors_id INTEGER REFERENCES evaluation_sample_errors(id),
  samples_compared INTEGER,
  out_of_domain TEXT NOT NULL DEFAULT '',
  PRIMARY KEY (run_id, capture_id)
);
INSERT INTO evaluation_capture_results_v5 (run_id, capture_id, sun_zenith_deg, sun_azimuth_deg,
                                           rmse, values_compared, sample_errors_id,
                                           samples_compared)
  SELECT r.run_id, r.capture_id, r.sun_zenith_deg, r.sun_azimuth_deg, r.rmse, r.values_compared,
         r.sample_errors_id,
         r.values_compared / (SELECT length(e.wavelengths_nm) / 8 FROM evaluation_runs e
                              WHERE e.id = r.run_id)
    FROM evaluation_capture_results r;
DROP TABLE evaluation_capture_results;
ALTER TABLE evaluation_capture_results_v5 RENAME TO evaluation_capture_results;
CREATE INDEX capture_results_by_sample_errors ON evaluation_capture_results(sample_errors_id);
CREATE TRIGGER sample_errors_follow_their_last_reference
AFTER DELETE ON evaluation_capture_results
WHEN OLD.sample_errors_id IS NOT NULL
BEGIN
  DELETE FROM evaluation_sample_errors WHERE id = OLD.sample_errors_id AND NOT EXISTS (
    SELECT 1 FROM evaluation_capture_results WHERE sample_errors_id = OLD.sample_errors_id);
END;

ALTER TABLE evaluation_runs ADD COLUMN out_of_domain TEXT NOT NULL DEFAULT 'exclude';
ALTER TABLE evaluation_runs ADD COLUMN samples_compared INTEGER;
ALTER TABLE evaluation_runs ADD COLUMN samples_excluded INTEGER;
ALTER TABLE evaluation_runs ADD COLUMN samples_clamped INTEGER;
ALTER TABLE evaluation_runs ADD COLUMN captures_unanswered INTEGER;
ALTER TABLE evaluation_runs ADD COLUMN compared_samples TEXT;
UPDATE evaluation_runs SET
  samples_compared = (SELECT CASE WHEN count(r.samples_compared) = count(*)
                                  THEN total(r.samples_compared) END
                        FROM evaluation_capture_results r WHERE r.run_id = evaluation_runs.id),
  samples_excluded = 0, samples_clamped = 0, captures_unanswered = 0,
  compared_samples = compared_samples_key((
    SELECT group_concat(line, char(10)) FROM (
      SELECT c.label || char(9) AS line FROM evaluation_capture_results r
        JOIN captures c ON c.id = r.capture_id
        WHERE r.run_id = evaluation_runs.id ORDER BY c.label)))
  WHERE status = 'succeeded';
)sql",
      // Version 6 (docs/data-api.md "Evaluation tickets" and "Durability"): evaluation tickets
      // are rows instead of server memory, so that they outlive the process and their ids are
      // never reused (AUTOINCREMENT). A ticket lists every requested model from the moment it is
      // accepted, in the order they run: `queued` until its run starts, then the run's id and
      // `running`, `succeeded` or `failed`; `skipped` when an earlier model of the ticket failed;
      // `interrupted` (with the reason) when the server stopped first. A model's run id has no
      // foreign key: the run goes with its dataset, the ticket keeps the id (as a run keeps its
      // job id). Tickets of earlier versions lived in memory: there are none to convert.
      R"sql(
CREATE TABLE evaluation_tickets (
  id INTEGER PRIMARY KEY AUTOINCREMENT,
  dataset TEXT NOT NULL,
  job_id INTEGER,
  status TEXT NOT NULL
    CHECK (status IN ('queued', 'running', 'succeeded', 'failed', 'interrupted')),
  created_utc TEXT NOT NULL,
  finished_utc TEXT,
  error TEXT
);
CREATE TABLE evaluation_ticket_models (
  ticket_id INTEGER NOT NULL REFERENCES evaluation_tickets(id) ON DELETE CASCADE,
  position INTEGER NOT NULL,
  model_id TEXT NOT NULL,
  run_id INTEGER,
  status TEXT NOT NULL
    CHECK (status IN ('queued', 'running', 'succeeded', 'failed', 'skipped', 'interrupted')),
  error TEXT,
  PRIMARY KEY (ticket_id, position)
);
CREATE INDEX tickets_by_status ON evaluation_tickets(status);
)sql",
      // Version 7 (docs/fits.md "Stored fits"): atmosphere fits. A fit names its dataset, model
      // and model version, the free parameters with their bounds and grid counts, the fixed
      // parameters, the search's table options and the captures it used, all as JSON text; it
      // is `running` with a progress and stage while computed, then `succeeded` with its values,
      // RMSE before, at the search setting and after, the cross-validated RMSE when asked, and
      // the per-capture results, uncertainty ranges, objective history and stage timings (JSON),
      // or `failed` / `interrupted` with the error. Ids are never reused (AUTOINCREMENT).
      R"sql(
CREATE TABLE fits (
  id INTEGER PRIMARY KEY AUTOINCREMENT,
  dataset_id INTEGER NOT NULL REFERENCES datasets(id) ON DELETE CASCADE,
  model_id TEXT NOT NULL,
  model_version TEXT NOT NULL,
  free_parameters TEXT NOT NULL,
  fixed_parameters TEXT NOT NULL,
  search_options TEXT NOT NULL,
  captures TEXT NOT NULL,
  settings TEXT NOT NULL,
  software_version TEXT NOT NULL,
  status TEXT NOT NULL
    CHECK (status IN ('queued', 'running', 'succeeded', 'failed', 'interrupted')),
  progress REAL NOT NULL DEFAULT 0,
  stage TEXT,
  result TEXT,
  rmse_before REAL,
  rmse_search REAL,
  rmse_after REAL,
  cross_validated_rmse REAL,
  per_capture TEXT,
  uncertainty TEXT,
  history TEXT,
  timings TEXT,
  error TEXT,
  created_utc TEXT NOT NULL,
  finished_utc TEXT
);
CREATE INDEX fits_by_dataset ON fits(dataset_id);
)sql",
      // Version 8 (docs/data-api.md "Jobs"): how many due occurrences of a job were skipped
      // because its previous run was still going, and the last time one was.
      R"sql(
ALTER TABLE jobs ADD COLUMN skipped_count INTEGER NOT NULL DEFAULT 0;
ALTER TABLE jobs ADD COLUMN last_skipped_utc TEXT;
)sql",
      // Version 9: users' AERONET phase-function inversions (docs/data-api.md "Aerosol inversions",
      // models/measured_aerosols/README.md): the file's bytes as uploaded, validated by the
      // reader of models/aeronet before the row is written, with what the reader found in it
      // (site, days, retrievals) and its FNV-1a content hash, which keys the model's tables in
      // the disk cache. Ids are never reused (AUTOINCREMENT): an id in a stored evaluation, job
      // or fit always means the same file.
      R"sql(
CREATE TABLE aerosol_inversions (
  id INTEGER PRIMARY KEY AUTOINCREMENT,
  name TEXT NOT NULL,
  content_hash TEXT NOT NULL,
  site TEXT NOT NULL,
  latitude_deg REAL NOT NULL,
  longitude_deg REAL NOT NULL,
  first_day TEXT NOT NULL,
  last_day TEXT NOT NULL,
  retrieval_count INTEGER NOT NULL CHECK (retrieval_count > 0),
  size_bytes INTEGER NOT NULL,
  content BLOB NOT NULL,
  created_utc TEXT NOT NULL
);
)sql",
      // Version 10 (docs/data-api.md "Dataset kinds", docs/measurement-formats.md "Broadband
      // irradiance"): a dataset is of one kind, `sky_radiance` (captures of spectral sky
      // radiance, every dataset stored before) or `broadband_irradiance` (a time series of
      // horizontal irradiance, W/m2, from a pyranometer or a weather file). An irradiance sample
      // is an instant (unix seconds with the UTC offset of its clock), a site, and any of
      // global horizontal (GHI), diffuse horizontal (DHI) and direct normal (DNI) irradiance,
      // at least one, with the period it averages when known. Instants may repeat (a logger
      // writing its clock to the tenth of a minute): samples keep their file order by id. An
      // evaluation run of such a dataset has, per measured component, its RMSE and mean bias
      // (model minus measured, W/m2) over the samples compared and every sample's error
      // (float64 blob in the dataset's sample order, NaN where not compared: the sun down or
      // the component not measured).
      R"sql(
ALTER TABLE datasets ADD COLUMN kind TEXT NOT NULL DEFAULT 'sky_radiance'
  CHECK (kind IN ('sky_radiance', 'broadband_irradiance'));
CREATE TABLE irradiance_samples (
  id INTEGER PRIMARY KEY,
  dataset_id INTEGER NOT NULL REFERENCES datasets(id) ON DELETE CASCADE,
  time_utc_s REAL NOT NULL,
  utc_offset_minutes INTEGER NOT NULL,
  latitude_deg REAL NOT NULL,
  longitude_deg REAL NOT NULL,
  elevation_m REAL NOT NULL,
  ghi_w_m2 REAL,
  dhi_w_m2 REAL,
  dni_w_m2 REAL,
  averaging_s REAL CHECK (averaging_s IS NULL OR averaging_s > 0),
  CHECK (ghi_w_m2 IS NOT NULL OR dhi_w_m2 IS NOT NULL OR dni_w_m2 IS NOT NULL)
);
CREATE INDEX irradiance_samples_by_dataset ON irradiance_samples(dataset_id, time_utc_s);
CREATE TABLE evaluation_irradiance_results (
  run_id INTEGER NOT NULL REFERENCES evaluation_runs(id) ON DELETE CASCADE,
  component TEXT NOT NULL CHECK (component IN ('ghi', 'dhi', 'dni')),
  rmse_w_m2 REAL,
  mean_bias_w_m2 REAL,
  samples_compared INTEGER NOT NULL,
  errors_w_m2 BLOB NOT NULL,
  PRIMARY KEY (run_id, component)
);
)sql",
      // Version 11 (docs/data-api.md "Jobs", docs/fits.md "In evaluations and jobs"): a job may
      // re-fit its dataset at each occurrence before evaluating it. `refit` is the fit request
      // (the body of POST /v1/fits without its dataset, as the API received it; NULL: the job
      // does not re-fit), kept apart from the evaluation parameters, which POST /v1/evaluations
      // checks; `last_fit_id` is the fit its newest occurrence made (NULL before the first or
      // once the fit is gone with its dataset).
      R"sql(
ALTER TABLE jobs ADD COLUMN refit TEXT;
ALTER TABLE jobs ADD COLUMN last_fit_id INTEGER REFERENCES fits(id) ON DELETE SET NULL;
)sql",
  };
  return migrations;
}

namespace {

// Foreign keys off while migrating, on again afterwards whatever happens: the rebuild of a
// table (SQLite's "making other kinds of table schema changes" procedure) drops the old table,
// which with foreign keys on would cascade to its children. The pragma is a no-op inside a
// transaction, so it is set around them; each migration checks the keys before committing.
class ForeignKeysOff {
 public:
  explicit ForeignKeysOff(Database& db) : db_(db) { db_.execute("PRAGMA foreign_keys = OFF"); }
  ~ForeignKeysOff() {
    try {
      db_.execute("PRAGMA foreign_keys = ON");
    } catch (...) {
      // Never thrown by SQLite outside a transaction; a destructor must not throw.
    }
  }
  ForeignKeysOff(const ForeignKeysOff&) = delete;
  ForeignKeysOff& operator=(const ForeignKeysOff&) = delete;

 private:
  Database& db_;
};

}  // namespace

int migrate(Database& db, const std::vector<std::string_view>& migrations) {
  const int latest = static_cast<int>(migrations.size());
  int applied = 0;
  register_legacy_run_parameters(db);
  register_compared_samples_key(db);
  const ForeignKeysOff keys_off(db);
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
    if (db.prepare("PRAGMA foreign_key_check").step())
      throw std::runtime_error("schema migration to version " + std::to_string(version + 1) +
                               " leaves rows whose foreign keys point nowhere");
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
