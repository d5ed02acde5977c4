// Versioned, checksummed table files with atomic replacement.
#include "server/cache/file_table_cache.h"

#include <spdlog/spdlog.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "models/core/content_hash.h"
#include "server/cache/table_checksum.h"

namespace clearsky::server {

namespace {

constexpr char kMagic[8] = {'C', 'S', 'K', 'Y', 'T', 'B', 'L', '\n'};

template <typename T>
void put(std::string& out, T value) {
  for (std::size_t i = 0; i < sizeof(T); ++i)
    out.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
}

template <typename T>
bool get(std::string_view& in, T& value) {
  if (in.size() < sizeof(T)) return false;
  value = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i)
    value |= static_cast<T>(static_cast<unsigned char>(in[i])) << (8 * i);
  in.remove_prefix(sizeof(T));
  return true;
}

}  // namespace

FileTableCache::FileTableCache(std::filesystem::path directory) : directory_(std::move(directory)) {
  std::filesystem::create_directories(directory_);
  // A writer killed between its temporary file and the rename leaves the file behind; one still
  // being written (by another process sharing the folder) is younger than this.
  if (const std::size_t stale = remove_stale_temporaries(kStaleTemporaryAge); stale > 0)
    spdlog::info("table cache: removed {} temporary files left by killed writers", stale);
}

std::filesystem::path FileTableCache::path_of(const std::string& key) const {
  return directory_ / (hex64(fnv1a_64(key)) + ".table");
}

std::optional<std::string> FileTableCache::load(const std::string& key) const {
  auto result = [&]() -> std::optional<std::string> {
    std::ifstream file(path_of(key), std::ios::binary);
    if (!file) return std::nullopt;
    std::ostringstream content;
    content << file.rdbuf();
    const std::string data = std::move(content).str();
    std::string_view in(data);
    // A damaged file is a miss like a missing one, but said in the log: the operator learns
    // why a start took the time of a build (docs/threat-model.md "corrupt or lose stored data").
    const auto damaged = [&](std::string_view why) -> std::optional<std::string> {
      spdlog::warn("table cache: {} {} ({} bytes), rebuilding", path_of(key).string(), why,
                   data.size());
      return std::nullopt;
    };
    if (in.size() < sizeof kMagic) return damaged("is truncated before its magic");
    if (std::memcmp(in.data(), kMagic, sizeof kMagic) != 0)
      return damaged("does not start with the table cache magic");
    in.remove_prefix(sizeof kMagic);
    std::uint32_t version = 0, key_length = 0;
    std::uint64_t payload_length = 0, checksum = 0;
    if (!get(in, version)) return damaged("is truncated in its header");
    if (version != kFormatVersion) {
      spdlog::info("table cache: {} has format version {} (this server writes {}), rebuilding",
                   path_of(key).string(), version, kFormatVersion);
      return std::nullopt;
    }
    if (!get(in, key_length) || in.size() < key_length) return damaged("is truncated in its key");
    if (in.substr(0, key_length) != key) {
      // Another key with the same file name (a hash collision): not damage, replaced.
      spdlog::info("table cache: {} holds another key, rebuilding", path_of(key).string());
      return std::nullopt;
    }
    in.remove_prefix(key_length);
    if (!get(in, payload_length) || !get(in, checksum))
      return damaged("is truncated in its header");
    if (in.size() < payload_length) return damaged("is truncated in its payload");
    if (in.size() != payload_length) return damaged("has bytes after its payload");
    if (table_checksum(in) != checksum) {
      spdlog::warn("table cache: checksum mismatch in {}, rebuilding", path_of(key).string());
      return std::nullopt;
    }
    return std::string(in);
  }();
  if (observer_) observer_(result.has_value());
  return result;
}

void FileTableCache::store(const std::string& key, std::string_view bytes) const {
  const std::filesystem::path target = path_of(key);
  std::string header(kMagic, sizeof kMagic);
  put(header, kFormatVersion);
  put(header, static_cast<std::uint32_t>(key.size()));
  header += key;
  put(header, static_cast<std::uint64_t>(bytes.size()));
  put(header, table_checksum(bytes));
  // mkstemp(3) creates the name with O_EXCL: unique even among processes of other hosts or
  // containers sharing the folder, where process ids repeat (every container's server may be
  // process 1), so two writers never write into one temporary file.
  std::string temporary = target.string() + kTemporaryInfix + "XXXXXX";
  const int fd = ::mkstemp(temporary.data());
  if (fd < 0) {
    spdlog::warn("table cache: cannot create a temporary file for {}: {}", target.string(),
                 std::strerror(errno));
    return;
  }
  const auto write_all = [fd](std::string_view data) {
    while (!data.empty()) {
      const ssize_t n = ::write(fd, data.data(), data.size());
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      data.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
  };
  // fsync before the rename: after a power cut the entry is the old file or the whole new one
  // (the rename reaches the disk after the data it names).
  const bool written =
      write_all(header) && write_all(bytes) && ::fchmod(fd, 0644) == 0 && ::fsync(fd) == 0;
  const int write_error = errno;
  const bool closed = ::close(fd) == 0;
  std::error_code error;
  if (!written || !closed) {
    spdlog::warn("table cache: cannot write {}: {}", temporary,
                 std::strerror(written ? errno : write_error));
    std::filesystem::remove(temporary, error);
    return;
  }
  std::filesystem::rename(temporary, target, error);
  if (error) {
    spdlog::warn("table cache: cannot rename {} to {}: {}", temporary, target.string(),
                 error.message());
    std::filesystem::remove(temporary, error);
  }
}

std::size_t FileTableCache::remove_stale_temporaries(std::chrono::seconds older_than) const {
  std::size_t removed = 0;
  std::error_code error;
  const auto now = std::filesystem::file_time_type::clock::now();
  for (auto it = std::filesystem::directory_iterator(directory_, error);
       !error && it != std::filesystem::directory_iterator(); it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.find(kTemporaryInfix) == std::string::npos) continue;
    std::error_code ignored;
    const auto modified = std::filesystem::last_write_time(it->path(), ignored);
    if (ignored || now - modified < older_than) continue;
    if (std::filesystem::remove(it->path(), ignored)) ++removed;
  }
  return removed;
}

}  // namespace clearsky::server
