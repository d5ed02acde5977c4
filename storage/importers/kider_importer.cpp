// Transactional, idempotent import of Kider captures (kider_importer.h).
#include "storage/importers/kider_importer.h"

#include <chrono>
#include <mutex>
#include <stdexcept>

#include "models/core/content_hash.h"
#include "models/core/parallel.h"
#include "models/evaluation/capture_preparation.h"
#include "storage/importers/import_conflict.h"
#include "storage/importers/kider_reader.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_name.h"
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

// The progress of several sources read in parallel, summed and passed on one call at a time.
class ProgressSum {
 public:
  ProgressSum(std::size_t sources, const std::function<void(const ImportProgress&)>& callback)
      : per_source_(sources), callback_(callback) {}

  KiderReadObserver observer(std::size_t source) {
    if (!callback_) return {};
    return [this, source](const KiderReadProgress& p) {
      std::lock_guard lock(mutex_);
      per_source_[source] = p;
      ImportProgress sum;
      sum.bytes_total = 0;
      sum.entries_total = 0;
      for (const KiderReadProgress& s : per_source_) {
        sum.bytes_read += s.bytes_read;
        sum.entries_read += s.entries_read;
        sum.files_read += s.files_read;
        sum.bytes_total =
            s.bytes_total < 0 || sum.bytes_total < 0 ? -1 : sum.bytes_total + s.bytes_total;
        sum.entries_total =
            s.entries_total < 0 || sum.entries_total < 0 ? -1 : sum.entries_total + s.entries_total;
      }
      last_ = sum;
      callback_(sum);
    };
  }
  ImportProgress last() const { return last_; }

 private:
  std::mutex mutex_;
  std::vector<KiderReadProgress> per_source_;
  const std::function<void(const ImportProgress&)>& callback_;
  ImportProgress last_;
};

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
  if (request.paths.empty() && request.archives_in_memory.empty())
    throw std::invalid_argument("import: no archive or folder given");
  if (!is_valid_dataset_name(request.dataset_name))
    throw InvalidDatasetName("dataset name: " + std::string(kDatasetNameRule));
  if (!request.path_names.empty() && request.path_names.size() != request.paths.size())
    throw std::invalid_argument("import: one name per path");
  ImportByteBudget budget(request.limits);

  // Read and decode everything first: a bad file is reported before any write.
  struct Decoded {
    std::string source;
    std::vector<MeasuredCapture> captures;
  };
  const std::size_t path_count = request.paths.size();
  std::vector<Decoded> decoded(path_count + request.archives_in_memory.size());
  ProgressSum reading(decoded.size(), request.progress);
  parallel_for(decoded.size(), [&](std::size_t i) {
    if (i < path_count) {
      KiderReadRules rules;
      rules.budget = &budget;
      rules.confine_to = request.confine_to;
      if (!request.path_names.empty()) rules.shown_as = request.path_names[i];
      decoded[i].source = request.path_names.empty() ? request.paths[i].string() : rules.shown_as;
      decoded[i].captures =
          decode_kider_files(read_kider_raw_files(request.paths[i], reading.observer(i), rules),
                             decoded[i].source, request.options);
    } else {
      const auto& upload = request.archives_in_memory[i - path_count];
      decoded[i].source = upload.name;
      decoded[i].captures = decode_kider_files(
          read_kider_archive_bytes(upload.bytes, upload.name, reading.observer(i), &budget),
          upload.name, request.options);
    }
  });
  std::size_t capture_count = 0;
  for (const Decoded& d : decoded) capture_count += d.captures.size();
  if (capture_count == 0)
    throw std::runtime_error(decoded.front().source + ": no Kider capture found");

  ImportProgress progress = reading.last();
  progress.phase = "writing";
  if (request.progress) request.progress(progress);

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
        throw ImportConflict(d.source + ": capture " + capture.label + " is already in dataset '" +
                             request.dataset_name + "' with different content (hash " +
                             existing->second + ", new " + hash + ")");
      compute_sun_position(capture);
      captures.insert(dataset_id, capture, hash, d.source);
      report.added.push_back(capture.label);
      report.samples_added += static_cast<std::int64_t>(capture.samples.size());
      ++written;
      if (request.after_capture_written) request.after_capture_written(written);
      progress.captures_added = written;
      progress.samples_added = report.samples_added;
      if (request.progress) request.progress(progress);
    }
  }
  transaction.commit();
  progress.phase = "committed";
  if (request.progress) request.progress(progress);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace clearsky::storage
