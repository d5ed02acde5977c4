// Import of Kider et al. 2014 captures (archives or folders) into a dataset, all in one
// transaction: every path is read and decoded before the database is touched, then written by
// capture_writer.h, so that a failure at any point (malformed file, truncated archive,
// conflict, crash) leaves the database as it was; re-importing the same content is a no-op.
// Spectra are stored as measured: sample 0 keeps its kSampleKnownDefective flag and is repaired
// by evaluations, not here. Progress (reading, then writing) is reported through an optional
// callback: the API's import jobs and the CLI share this code.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "storage/importers/capture_writer.h"
#include "storage/importers/import_byte_budget.h"
#include "storage/importers/kider_format.h"
#include "storage/sqlite/database.h"

namespace clearsky::storage {

// The format of the datasets Kider archives are imported into.
constexpr std::string_view kKiderDatasetFormat = "kider2014";

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

// Throws std::runtime_error naming the source when nothing holds a Kider capture (before any
// write, so not even the dataset is created), InvalidDatasetName for a name outside the rule,
// ImportLimitExceeded past a byte limit.
class InvalidDatasetName : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

ImportReport import_kider(Database& db, const KiderImportRequest& request);

}  // namespace clearsky::storage
