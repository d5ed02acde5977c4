// Transactional, idempotent import of Kider captures (kider_importer.h).
#include "storage/importers/kider_importer.h"

#include <chrono>
#include <stdexcept>

#include "models/core/content_hash.h"
#include "models/core/parallel.h"
#include "models/evaluation/capture_preparation.h"
#include "storage/importers/kider_reader.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"

namespace clearsky::storage {
namespace {

std::uint64_t hash_bytes(std::uint64_t h, const void* data, std::size_t size) {
  return fnv1a_64(std::string_view(static_cast<const char*>(data), size), h);
}

template <typename T>
std::uint64_t hash_value(std::uint64_t h, const T& value) {
  return hash_bytes(h, &value, sizeof value);
}

}  // namespace

std::string capture_content_hash(const MeasuredCapture& capture) {
  std::uint64_t h = fnv1a_64(capture.label);
  h = hash_value(h, capture.unix_time_utc_s);
  h = hash_value(h, capture.utc_offset_minutes);
  h = hash_value(h, capture.site.latitude_deg);
  h = hash_value(h, capture.site.longitude_deg);
  h = hash_value(h, capture.site.elevation_m);
  for (const MeasuredSample& s : capture.samples) {
    h = hash_value(h, s.index);
    h = hash_value(h, s.view.zenith_rad);
    h = hash_value(h, s.view.azimuth_rad);
    h = hash_value(h, s.quality_flags);
    const auto& nm = s.radiance.wavelengths_nm();
    const auto& values = s.radiance.values();
    h = hash_value(h, nm.size());
    h = hash_bytes(h, nm.data(), nm.size() * sizeof(double));
    h = hash_bytes(h, values.data(), values.size() * sizeof(double));
  }
  return hex64(h);
}

ImportReport import_kider(Database& db, const KiderImportRequest& request) {
  const auto start = std::chrono::steady_clock::now();
  if (request.paths.empty()) throw std::invalid_argument("import: no archive or folder given");

  // Read and decode everything first: a bad file is reported before any write.
  struct Decoded {
    std::string source;
    std::vector<MeasuredCapture> captures;
  };
  std::vector<Decoded> decoded(request.paths.size());
  parallel_for(request.paths.size(), [&](std::size_t i) {
    decoded[i].source = request.paths[i].string();
    decoded[i].captures = read_kider_path(request.paths[i], request.options);
  });

  ImportReport report;
  report.dataset = request.dataset_name;
  Transaction transaction(db);
  DatasetRepository datasets(db);
  CaptureRepository captures(db);
  const std::int64_t dataset_id = datasets.find_or_create(request.dataset_name, "kider2014");
  int written = 0;
  for (Decoded& d : decoded) {
    for (MeasuredCapture& capture : d.captures) {
      const std::string hash = capture_content_hash(capture);
      if (captures.find_by_hash(dataset_id, hash)) {
        report.unchanged.push_back(capture.label);
        continue;
      }
      if (const auto existing = captures.find_by_label(dataset_id, capture.label))
        throw std::runtime_error(d.source + ": capture " + capture.label + " is already in dataset '" +
                                 request.dataset_name + "' with different content (hash " + existing->second +
                                 ", new " + hash + ")");
      compute_sun_position(capture);
      captures.insert(dataset_id, capture, hash, d.source);
      report.added.push_back(capture.label);
      report.samples_added += static_cast<std::int64_t>(capture.samples.size());
      ++written;
      if (request.after_capture_written) request.after_capture_written(written);
    }
  }
  transaction.commit();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace clearsky::storage
