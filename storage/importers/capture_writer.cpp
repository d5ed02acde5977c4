// One-transaction, idempotent writing of decoded captures (capture_writer.h).
#include "storage/importers/capture_writer.h"

#include "models/core/content_hash.h"
#include "models/evaluation/capture_preparation.h"
#include "storage/importers/import_conflict.h"
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

ImportReport write_captures(Database& db, std::vector<DecodedCaptures>& decoded,
                            const CaptureWrite& write, ImportProgress progress) {
  progress.phase = "writing";
  if (write.progress) write.progress(progress);

  ImportReport report;
  report.dataset = write.dataset_name;
  Transaction transaction(db);
  DatasetRepository datasets(db);
  CaptureRepository captures(db);
  const std::int64_t dataset_id = datasets.find_or_create(write.dataset_name, write.dataset_format);
  int written = 0;
  for (DecodedCaptures& d : decoded) {
    for (MeasuredCapture& capture : d.captures) {
      const std::string hash = capture_content_hash(capture);
      if (captures.find_by_hash(dataset_id, hash)) {
        report.unchanged.push_back(capture.label);
        continue;
      }
      if (const auto existing = captures.find_by_label(dataset_id, capture.label))
        throw ImportConflict(d.source + ": capture " + capture.label + " is already in dataset '" +
                             write.dataset_name + "' with different content (hash " +
                             existing->second + ", new " + hash + ")");
      compute_sun_position(capture);
      captures.insert(dataset_id, capture, hash, d.source);
      report.added.push_back(capture.label);
      report.samples_added += static_cast<std::int64_t>(capture.samples.size());
      ++written;
      if (write.after_capture_written) write.after_capture_written(written);
      progress.captures_added = written;
      progress.samples_added = report.samples_added;
      if (write.progress) write.progress(progress);
    }
  }
  transaction.commit();
  progress.phase = "committed";
  if (write.progress) write.progress(progress);
  return report;
}

}  // namespace clearsky::storage
