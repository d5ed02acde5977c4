// Writing decoded captures into a dataset, the step every importer shares (the Kider archives'
// kider_importer.h and the open sky-radiance format's api/datasets/sky_radiance_import.h): one
// transaction, so that a failure (a conflict, a full disk, a crash) leaves the database as it
// was. A capture already present with the same content (capture_content_hash) is left
// unchanged, so re-importing is a no-op; the same label with other content is an
// ImportConflict. The computed sun position (SPA, no refraction, as the study) is stored with
// each capture added, from its own time and site.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "models/evaluation/measured_sky.h"
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

struct ImportReport {
  std::string dataset;
  std::vector<std::string> added;      // capture labels
  std::vector<std::string> unchanged;  // already present with the same content
  std::int64_t samples_added = 0;
  double seconds = 0;
};

// The captures decoded from one source (an archive, a folder, an uploaded file), named in
// messages and stored as each capture's source.
struct DecodedCaptures {
  std::string source;
  std::vector<MeasuredCapture> captures;
};

struct CaptureWrite {
  std::string dataset_name;
  std::string dataset_format;  // stored with a new dataset; an existing one must have it
  // Called after each new capture is written, inside the transaction (tests interrupt an
  // import half-way with it).
  std::function<void(int captures_written)> after_capture_written;
  // Called with progress (phase writing, then committed), from the calling thread.
  std::function<void(const ImportProgress&)> progress;
};

// Writes the captures (their sun positions computed here); progress starts from `read`, the
// progress of the reading. Throws ImportConflict (import_conflict.h) for a label held with
// other content or a dataset of another format, SqliteError when the database fails. The
// report's seconds are left 0.
ImportReport write_captures(Database& db, std::vector<DecodedCaptures>& decoded,
                            const CaptureWrite& write, ImportProgress read = {});

// 16 hex digits identifying a capture's content: label, time, site and every sample's index,
// direction, flags, wavelengths and values.
std::string capture_content_hash(const MeasuredCapture& capture);

}  // namespace clearsky::storage
