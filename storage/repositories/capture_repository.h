// Captures and their samples as stored: spectra as measured (float64 blobs of wavelengths and
// radiance), quality flags, the site and time, the computed sun position and, once an
// evaluation estimated it, the estimated sun azimuth. SQL on captures and samples lives only
// here. Thread-safety: as the Database it uses.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "models/evaluation/measured_sky.h"
#include "storage/sqlite/database.h"

namespace clearsky::storage {

struct StoredCapture {
  std::int64_t id = 0;
  std::string content_hash;
  std::string source;
  MeasuredCapture capture;
};

class CaptureRepository {
 public:
  explicit CaptureRepository(Database& db) : db_(db) {}
  std::optional<std::int64_t> find_by_hash(std::int64_t dataset_id, const std::string& content_hash);
  // The id and content hash of the capture with this label.
  std::optional<std::pair<std::int64_t, std::string>> find_by_label(std::int64_t dataset_id, const std::string& label);
  // Inserts a capture and its samples (call inside a Transaction); returns its id.
  std::int64_t insert(std::int64_t dataset_id, const MeasuredCapture& capture, const std::string& content_hash,
                      const std::string& source);
  // Every capture of a dataset with its samples, in time order.
  std::vector<StoredCapture> load(std::int64_t dataset_id);
  void set_estimated_sun_azimuth(std::int64_t capture_id, double azimuth_deg);

 private:
  Database& db_;
};

}  // namespace clearsky::storage
