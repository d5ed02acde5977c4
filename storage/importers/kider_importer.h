// Import of Kider et al. 2014 captures (archives or folders) into a dataset, all in one
// transaction: every path is read and decoded before the database is touched, and a failure
// at any point (malformed file, truncated archive, conflict, crash) leaves the database as it
// was. A capture already present with the same content (hash of its decoded samples, time
// and site) is left unchanged, so re-importing is a no-op; the same label with other content
// is a conflict. Spectra are stored as measured: sample 0 keeps its kSampleKnownDefective
// flag and is repaired by evaluations, not here. The computed sun position (SPA, no
// refraction, as the study) is stored with each capture. Progress (reading, then writing) is
// reported through an optional callback: the API's import jobs and the CLI share this code.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "storage/importers/import_byte_budget.h"
#include "storage/importers/kider_format.h"
#include "storage/sqlite/database.h"

namespace clearsky::storage {

// How far an import has come: the sums over its archives and folders (kider_reader.h), then
// the captures written. Totals are -1 while unknown.
struct ImportProgress {
  std::string phase = "reading";  // reading, writing, committed
  std::int64_t bytes_read = 0;
  std::int64_t bytes_total = -1;
  std::int64_t entries_read = 0;
  std::int64_t entries_total = -1;
  std::int64_t files_read = 0;
  std::int64_t captures_added = 0;
  std::int64_t samples_added = 0;
};

struct KiderImportRequest {
  std::string dataset_name = "kider2014";    // storage/repositories/dataset_name.h
  std::vector<std::filesystem::path> paths;  // .7z archives or folders
  // The bytes the whole import may read, counted as it reads (import_byte_budget.h).
  ImportByteLimits limits;
  // Non-empty for server-side paths: the canonical import root the paths resolved in; the
  // paths must then be canonical, and nothing outside the root is read (kider_reader.h).
  std::filesystem::path confine_to;
  // The paths' names in messages and reports, when not the paths themselves (a server-side
  // import names the path as requested); empty, or one per path.
  std::vector<std::string> path_names;
  // Archives held in memory (uploads): a name for messages and the archive's bytes.
  struct ArchiveBytes {
    std::string name;
    std::string bytes;
  };
  std::vector<ArchiveBytes> archives_in_memory;
  KiderImportOptions options;
  // Called after each new capture is written, inside the transaction (tests use it to
  // interrupt an import half-way).
  std::function<void(int captures_written)> after_capture_written;
  // Called with the progress, from the reading threads (serialised: one call at a time) and
  // then the importing thread. Must be quick; it must not touch the importing Database.
  std::function<void(const ImportProgress&)> progress;
};

struct ImportReport {
  std::string dataset;
  std::vector<std::string> added;      // capture labels
  std::vector<std::string> unchanged;  // already present with the same content
  std::int64_t samples_added = 0;
  double seconds = 0;
};

// Throws std::runtime_error naming the source when nothing holds a Kider capture (before any
// write, so not even the dataset is created), InvalidDatasetName for a name outside the rule,
// ImportLimitExceeded past a byte limit.
class InvalidDatasetName : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

ImportReport import_kider(Database& db, const KiderImportRequest& request);

// 16 hex digits identifying a capture's content: label, time, site and every sample's index,
// direction, flags, wavelengths and values.
std::string capture_content_hash(const MeasuredCapture& capture);

}  // namespace clearsky::storage
