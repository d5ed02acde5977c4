// The on-disk TableCache (models/core/precompute_context.h): one file per key under a
// directory, named by the key's FNV-1a hash (a short string: the names stay those of every
// earlier version). A file is trusted only when its header matches:
//
//   offset  size  field
//   0       8     magic "CSKYTBL\n"
//   8       4     format version (little-endian uint32, kFormatVersion)
//   12      4     key length K (uint32)
//   16      K     the key itself (compared in full: a hash collision or a stale file is a miss)
//   16+K    8     payload length N (uint64)
//   24+K    8     XXH3 64 checksum of the payload (table_checksum.h)
//   32+K    N     payload
//
// Version 1 files carried an FNV-1a checksum: a file of another version is a miss, logged, and
// rebuilt (its checksum is never read as this version's). A missing, truncated, stale or
// corrupt file is a miss (the model rebuilds and stores again, replacing it); every one but a
// missing file is logged with the reason (truncated, bad magic, checksum mismatch, another
// key). Writes go to a temporary file in the same directory created by mkstemp(3) (unique among
// all the processes sharing the directory, replicas in other containers included,
// docs/deploy.md "Shared table cache"), fsync(2)ed, then rename(2) replaces the entry
// atomically, so readers never see a partial file and the last complete write wins. Temporary
// files a killed writer left behind are removed when a cache is opened, once older than
// kStaleTemporaryAge. Store failures are logged and otherwise ignored (the cache is an
// optimisation).
// Thread-safety: load() and store() may be called concurrently from any thread and process.
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>

#include "models/core/precompute_context.h"

namespace clearsky::server {

class FileTableCache final : public TableCache {
 public:
  // 2: the payload checksum is XXH3 64 (1: FNV-1a 64).
  static constexpr std::uint32_t kFormatVersion = 2;
  // In the name of every temporary file: "<entry>.tmp.XXXXXX".
  static constexpr const char* kTemporaryInfix = ".tmp.";
  // A temporary file untouched for this long belongs to a writer that died.
  static constexpr std::chrono::seconds kStaleTemporaryAge{3600};

  // Creates directory when missing (std::filesystem_error when it cannot).
  explicit FileTableCache(std::filesystem::path directory);

  std::optional<std::string> load(const std::string& key) const override;
  void store(const std::string& key, std::string_view bytes) const override;

  std::filesystem::path path_of(const std::string& key) const;
  // Called after each load with whether it hit (for metrics); set before concurrent use.
  void set_observer(std::function<void(bool hit)> observer) { observer_ = std::move(observer); }
  // Removes the temporary files not modified for older_than; returns how many.
  std::size_t remove_stale_temporaries(std::chrono::seconds older_than) const;

 private:
  std::filesystem::path directory_;
  std::function<void(bool)> observer_;
};

}  // namespace clearsky::server
