// An uploaded request body spooled to a temporary file as it arrives, under a size limit, so
// that an archive is never held whole in memory (docs/architecture.md "Storage and durability").
// The file lives in the given folder with a unique name and is removed when the spool is
// destroyed, whatever happened. Not thread-safe: one spool per request.
#pragma once

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <string_view>

namespace clearsky::api {

// Removes the spool files a killed process left in folder (at start-up, before any upload);
// returns how many.
int remove_stale_uploads(const std::filesystem::path& folder);

class UploadSpool {
 public:
  // Creates the folder if needed and an empty file in it. suffix (e.g. ".7z") helps tools
  // that look at names. Throws std::runtime_error when the file cannot be created.
  UploadSpool(const std::filesystem::path& folder, std::size_t max_bytes,
              std::string_view suffix = "");
  UploadSpool(const UploadSpool&) = delete;
  UploadSpool& operator=(const UploadSpool&) = delete;
  ~UploadSpool();

  // Appends a chunk; throws ApiError 413 (too_large) beyond max_bytes, ApiError 507
  // (insufficient_storage, "disk") when the disk is full or the file size limit is reached,
  // std::runtime_error on another write error.
  void append(std::string_view chunk);
  // Flushes and closes (the errors of append); returns the file's path (valid until the spool
  // is destroyed).
  const std::filesystem::path& finish();

  std::size_t size_bytes() const { return size_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::FILE* file_ = nullptr;
  std::size_t max_bytes_;
  std::size_t size_ = 0;
};

}  // namespace clearsky::api
