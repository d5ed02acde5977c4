// Transactional, idempotent import of Kider captures (kider_importer.h).
#include "storage/importers/kider_importer.h"

#include <chrono>
#include <mutex>
#include <stdexcept>

#include "models/core/parallel.h"
#include "storage/importers/kider_reader.h"
#include "storage/repositories/dataset_name.h"

namespace clearsky::storage {
namespace {

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
  const std::size_t path_count = request.paths.size();
  std::vector<DecodedCaptures> decoded(path_count + request.archives_in_memory.size());
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
  for (const DecodedCaptures& d : decoded) capture_count += d.captures.size();
  if (capture_count == 0)
    throw std::runtime_error(decoded.front().source + ": no Kider capture found");

  CaptureWrite write;
  write.dataset_name = request.dataset_name;
  write.dataset_format = std::string(kKiderDatasetFormat);
  write.after_capture_written = request.after_capture_written;
  write.progress = request.progress;
  ImportReport report = write_captures(db, decoded, write, reading.last());
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace clearsky::storage
