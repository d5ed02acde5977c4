// Upload spooling to a temporary file (upload_spool.h).
#include "api/datasets/upload_spool.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include "api/error/api_error.h"

namespace clearsky::api {
namespace {

// A write that failed because the disk is full (ENOSPC), the user's quota is used (EDQUOT), or
// the file reached the process's size limit (EFBIG, RLIMIT_FSIZE) is 507 naming the disk; any
// other failure is internal.
[[noreturn]] void throw_write_failure(int error, const std::filesystem::path& path) {
  if (error == ENOSPC || error == EDQUOT || error == EFBIG)
    throw insufficient_storage("spooling the upload");
  throw std::runtime_error("cannot write upload file " + path.string() + ": " +
                           std::strerror(error));
}

}  // namespace

int remove_stale_uploads(const std::filesystem::path& folder) {
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) return 0;
  int removed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    if (entry.path().filename().string().rfind("upload-", 0) == 0 &&
        std::filesystem::remove(entry.path(), error))
      ++removed;
  }
  return removed;
}

UploadSpool::UploadSpool(const std::filesystem::path& folder, std::size_t max_bytes,
                         std::string_view suffix)
    : max_bytes_(max_bytes) {
  std::filesystem::create_directories(folder);
  // mkstemps: a unique name created atomically (no race between naming and opening).
  std::string name = (folder / "upload-XXXXXX").string() + std::string(suffix);
  const int fd = ::mkstemps(name.data(), static_cast<int>(suffix.size()));
  if (fd < 0 && (errno == ENOSPC || errno == EDQUOT))
    throw insufficient_storage("creating the upload file");
  if (fd < 0)
    throw std::runtime_error("cannot create an upload file in " + folder.string() + ": " +
                             std::strerror(errno));
  path_ = name;
  file_ = ::fdopen(fd, "wb");
  if (file_ == nullptr) {
    ::close(fd);
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
    throw std::runtime_error("cannot open upload file " + path_.string());
  }
}

UploadSpool::~UploadSpool() {
  if (file_ != nullptr) std::fclose(file_);
  std::error_code ignored;
  std::filesystem::remove(path_, ignored);
}

void UploadSpool::append(std::string_view chunk) {
  if (file_ == nullptr) throw std::logic_error("upload spool: append after finish");
  if (chunk.size() > max_bytes_ - size_)
    throw too_large("body",
                    "the upload is above the limit of " + std::to_string(max_bytes_) + " bytes");
  errno = 0;
  if (!chunk.empty() && std::fwrite(chunk.data(), 1, chunk.size(), file_) != chunk.size())
    throw_write_failure(errno, path_);
  size_ += chunk.size();
}

const std::filesystem::path& UploadSpool::finish() {
  if (file_ != nullptr) {
    errno = 0;
    const bool flushed = std::fflush(file_) == 0;
    const int flush_error = errno;
    const bool closed = std::fclose(file_) == 0;
    const int close_error = errno;
    file_ = nullptr;
    if (!flushed) throw_write_failure(flush_error, path_);
    if (!closed) throw_write_failure(close_error, path_);
  }
  return path_;
}

}  // namespace clearsky::api
