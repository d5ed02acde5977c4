// The byte budget of one import: how much one archive entry or folder file may hold
// (max_entry_bytes) and how much all the entries an import reads may hold together
// (max_import_bytes). Bytes are counted as they are read, never taken from the sizes an
// archive declares, and nothing is reserved ahead: a small archive that declares or inflates to
// gigabytes is refused once the bytes read pass the budget, with at most one read buffer more in
// memory (docs/data-api.md "Import limits", docs/threat-model.md).
//
// clang-format off
// | limit            | unit | default | sized from                                                                      |
// |------------------|------|---------|---------------------------------------------------------------------------------|
// | max_entry_bytes  | byte | 16 MiB  | a published Kider et al. 2014 .7z is 1.43 MB, a radiance file 61.5 KB           |
// | max_import_bytes | byte | 256 MiB | the 15 published captures in one tar of .7z read 107.5 MB (23.1 MB + 84.4 MB)   |
// clang-format on
// An entry's bytes are those of the radiance file or of the nested archive (whose own entries
// are counted again as they are read), a folder's those of each radiance file.
// Thread-safety: charge() may be called from several threads (the sources of one import are
// read in parallel); the import total is atomic.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace clearsky::storage {

struct ImportByteLimits {
  std::int64_t max_entry_bytes = std::int64_t{16} << 20;
  std::int64_t max_import_bytes = std::int64_t{256} << 20;
};

// An import read past one of its limits; limit() is its name (max_entry_bytes or
// max_import_bytes), what() names the entry.
class ImportLimitExceeded : public std::runtime_error {
 public:
  ImportLimitExceeded(std::string limit, std::int64_t limit_bytes, const std::string& message)
      : std::runtime_error(message), limit_(std::move(limit)), limit_bytes_(limit_bytes) {}
  const std::string& limit() const { return limit_; }
  std::int64_t limit_bytes() const { return limit_bytes_; }

 private:
  std::string limit_;
  std::int64_t limit_bytes_;
};

class ImportByteBudget {
 public:
  explicit ImportByteBudget(const ImportByteLimits& limits = {}) : limits_(limits) {}
  ImportByteBudget(const ImportByteBudget&) = delete;
  ImportByteBudget& operator=(const ImportByteBudget&) = delete;

  // Counts n more bytes of the entry named what, of which entry_bytes were read before (and
  // updated); throws ImportLimitExceeded, before the bytes are kept, when the entry or the
  // import would pass its limit.
  void charge(std::int64_t& entry_bytes, std::size_t n, const std::string& what);

  const ImportByteLimits& limits() const { return limits_; }
  std::int64_t import_bytes() const { return import_bytes_.load(); }

 private:
  ImportByteLimits limits_;
  std::atomic<std::int64_t> import_bytes_{0};
};

}  // namespace clearsky::storage
