// Kider captures from .7z archives (libarchive) and folders (kider_reader.h).
#include "storage/importers/kider_reader.h"

#include <archive.h>
#include <archive_entry.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "storage/importers/path_containment.h"

namespace clearsky::storage {
namespace {

struct ArchiveDeleter {
  void operator()(archive* a) const noexcept { archive_read_free(a); }
};

// libarchive's last error message (it may have none).
std::string error_text(archive* a) {
  const char* text = archive_error_string(a);
  return text != nullptr ? text : "unknown libarchive error";
}

std::string base_name_of(const std::string& path) {
  const auto slash = path.find_last_of("/\\");
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

bool is_radiance_file(const std::string& path) {
  return parse_kider_file_name(base_name_of(path)).has_value();
}

using ArchivePointer = std::unique_ptr<archive, ArchiveDeleter>;

// An open file descriptor (-1: none), closed when it goes.
class FileDescriptor {
 public:
  explicit FileDescriptor(int fd = -1) : fd_(fd) {}
  FileDescriptor(FileDescriptor&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
  FileDescriptor& operator=(FileDescriptor&&) = delete;
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }
  bool is_open() const { return fd_ >= 0; }

 private:
  int fd_;
};

// Opens path for reading if it is a regular file; a closed descriptor for a device, fifo or
// socket (opened without blocking, so that a fifo with no writer cannot hold the reader) or,
// when no_follow, a symbolic link. Throws when the file cannot be opened at all.
// name is the file's name in messages.
FileDescriptor open_regular_file(const std::filesystem::path& path, bool no_follow,
                                 const std::string& name) {
  const int flags = O_RDONLY | O_NONBLOCK | O_CLOEXEC | (no_follow ? O_NOFOLLOW : 0);
  FileDescriptor fd(::open(path.c_str(), flags));
  if (!fd.is_open()) {
    if (no_follow && errno == ELOOP) return FileDescriptor();
    throw std::runtime_error(name + ": cannot open: " + std::strerror(errno));
  }
  struct stat status {};
  if (::fstat(fd.get(), &status) != 0)
    throw std::runtime_error(name + ": cannot stat: " + std::strerror(errno));
  if (!S_ISREG(status.st_mode)) return FileDescriptor();
  return fd;
}

// The name of the path read in messages (KiderReadRules::shown_as).
std::string shown(const KiderReadRules& rules, const std::filesystem::path& path) {
  return rules.shown_as.empty() ? path.string() : rules.shown_as;
}

ArchivePointer new_reader() {
  ArchivePointer reader(archive_read_new());
  if (!reader) throw std::runtime_error("libarchive: out of memory");
  archive_read_support_filter_all(reader.get());
  // Archive formats only. Not format_all: its text formats would take any text for an archive
  // (raw, empty), and mtree, a manifest naming files, makes libarchive open those files on
  // the server's own disk.
  archive_read_support_format_7zip(reader.get());
  archive_read_support_format_zip(reader.get());
  archive_read_support_format_tar(reader.get());
  archive_read_support_format_gnutar(reader.get());
  archive_read_support_format_cpio(reader.get());
  archive_read_support_format_rar(reader.get());
  archive_read_support_format_rar5(reader.get());
  return reader;
}

// Archives that may hold the radiance files one level down (a tar or zip of the published .7z
// files); deeper nesting is not followed.
bool is_nested_archive(const std::string& path) {
  std::string name = base_name_of(path);
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* suffix : {".7z", ".zip", ".tar", ".tgz", ".tar.gz", ".tar.xz", ".tar.bz2"}) {
    const std::string_view s(suffix);
    if (name.size() > s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0)
      return true;
  }
  return false;
}

// Progress of one archive read; bytes are counted on the outermost archive.
struct ReadState {
  ImportByteBudget* budget = nullptr;
  KiderReadProgress progress;
  const KiderReadObserver* observer = nullptr;
  archive* outer = nullptr;
  void report() {
    if (outer != nullptr) progress.bytes_read = archive_filter_bytes(outer, -1);
    if (observer != nullptr && *observer) (*observer)(progress);
  }
};

// At the end of an archive its entry count is known, and every byte is accounted for (7z
// readers seek past what they do not need, so the bytes consumed may stay below the size).
void finish_reading(ReadState& state) {
  state.progress.entries_total = state.progress.entries_read;
  if (state.progress.bytes_total >= 0) state.progress.bytes_read = state.progress.bytes_total;
  state.outer = nullptr;
  state.report();
}

// The entry's bytes, counted against the budget as they are read: the size the entry declares
// is only compared at the end (a truncated entry), never used to reserve memory.
std::string read_entry_bytes(archive* reader, archive_entry* entry, const std::string& name,
                             const std::string& inner, ImportByteBudget& budget) {
  std::string bytes;
  std::int64_t entry_bytes = 0;
  char buffer[1 << 16];
  for (;;) {
    const la_ssize_t n = archive_read_data(reader, buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0)
      throw std::runtime_error(name + ": " + inner +
                               ": corrupt or truncated archive: " + error_text(reader));
    budget.charge(entry_bytes, static_cast<std::size_t>(n), name + ": " + inner);
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
  if (archive_entry_size_is_set(entry) &&
      bytes.size() != static_cast<std::size_t>(archive_entry_size(entry)))
    throw std::runtime_error(name + ": " + inner + ": truncated archive entry");
  return bytes;
}

// The radiance files of an opened archive (and of the archives it holds when nested is true),
// appended to files with prefix before their paths.
void read_entries(archive* reader, const std::string& name, const std::string& prefix, bool nested,
                  ReadState& state, std::vector<KiderRawFile>& files) {
  archive_entry* entry = nullptr;
  for (;;) {
    const int status = archive_read_next_header(reader, &entry);
    if (status == ARCHIVE_EOF) break;
    if (status != ARCHIVE_OK && status != ARCHIVE_WARN)
      throw std::runtime_error(name + ": corrupt or truncated archive: " + error_text(reader));
    if (archive_entry_filetype(entry) != AE_IFREG) continue;
    ++state.progress.entries_read;
    const char* entry_path = archive_entry_pathname(entry);
    const std::string inner = entry_path ? entry_path : "";
    if (is_radiance_file(inner)) {
      files.push_back(
          {prefix + inner, read_entry_bytes(reader, entry, name, inner, *state.budget)});
      ++state.progress.files_read;
    } else if (nested && is_nested_archive(inner)) {
      const std::string bytes = read_entry_bytes(reader, entry, name, inner, *state.budget);
      ArchivePointer inner_reader = new_reader();
      const std::string inner_name = name + ":" + inner;
      if (archive_read_open_memory(inner_reader.get(), bytes.data(), bytes.size()) != ARCHIVE_OK)
        throw std::runtime_error(inner_name +
                                 ": cannot open archive: " + error_text(inner_reader.get()));
      read_entries(inner_reader.get(), inner_name, prefix + inner + "/", false, state, files);
    }
    state.report();
  }
}

// Confined reads open the canonical path without following a link (a link swapped in after the
// path was resolved is refused).
std::vector<KiderRawFile> read_archive_files(const std::filesystem::path& path,
                                             const KiderReadObserver& observer,
                                             const KiderReadRules& rules,
                                             ImportByteBudget& budget) {
  const std::string name = shown(rules, path);
  const bool confined = !rules.confine_to.empty();
  if (confined && !lies_within(path, rules.confine_to))
    throw std::runtime_error(name + ": not inside the import root");
  const FileDescriptor fd = open_regular_file(path, confined, name);
  if (!fd.is_open()) throw std::runtime_error(name + ": not a regular file or folder");
  ArchivePointer reader = new_reader();
  if (archive_read_open_fd(reader.get(), fd.get(), 1 << 16) != ARCHIVE_OK)
    throw std::runtime_error(name + ": cannot open archive: " + error_text(reader.get()));
  ReadState state;
  state.budget = &budget;
  state.observer = &observer;
  state.outer = reader.get();
  struct stat status {};
  if (::fstat(fd.get(), &status) == 0) state.progress.bytes_total = status.st_size;
  std::vector<KiderRawFile> files;
  read_entries(reader.get(), name, "", true, state, files);
  finish_reading(state);
  return files;
}

// The bytes of an open regular file, counted against the budget as they are read.
std::string read_file_bytes(const FileDescriptor& fd, const std::string& name,
                            ImportByteBudget& budget) {
  std::string bytes;
  std::int64_t entry_bytes = 0;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd.get(), buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(name + ": read error: " + std::strerror(errno));
    }
    budget.charge(entry_bytes, static_cast<std::size_t>(n), name);
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
  return bytes;
}

// A radiance file of a folder: where it was listed, and what is opened (its canonical target
// when a confined read follows a link that stays inside the folder).
struct FolderFile {
  std::filesystem::path listed;
  std::filesystem::path target;
};

// Confined reads follow a link only when its canonical target lies inside rules.confine_to
// (the recursive listing never follows links to folders), and open the target without
// following a link.
std::vector<KiderRawFile> read_folder_files(const std::filesystem::path& folder,
                                            const KiderReadObserver& observer,
                                            const KiderReadRules& rules, ImportByteBudget& budget) {
  const bool confined = !rules.confine_to.empty();
  if (confined && !lies_within(folder, rules.confine_to))
    throw std::runtime_error(shown(rules, folder) + ": not inside the import root");
  // Listed first so that progress has totals.
  std::vector<FolderFile> radiance;
  ReadState state;
  state.budget = &budget;
  state.observer = &observer;
  state.progress.bytes_total = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (!is_radiance_file(entry.path().filename().string())) continue;
    FolderFile file{entry.path(), entry.path()};
    if (confined && entry.is_symlink()) {
      std::error_code error;
      file.target = std::filesystem::canonical(entry.path(), error);
      if (error || !lies_within(file.target, rules.confine_to)) continue;
    }
    std::error_code error;
    if (!std::filesystem::is_regular_file(file.target, error)) continue;
    const auto size = std::filesystem::file_size(file.target, error);
    if (error) continue;
    state.progress.bytes_total += static_cast<std::int64_t>(size);
    radiance.push_back(std::move(file));
  }
  state.progress.entries_total = static_cast<std::int64_t>(radiance.size());
  std::vector<KiderRawFile> files;
  for (const FolderFile& file : radiance) {
    // Lexically: std::filesystem::relative would resolve a link to its target's path.
    const std::string relative = file.listed.lexically_relative(folder).generic_string();
    const std::string name = shown(rules, folder) + "/" + relative;
    const FileDescriptor fd = open_regular_file(file.target, confined, name);
    // Replaced by a special file or a link since it was listed.
    if (!fd.is_open()) throw std::runtime_error(name + ": not a regular file");
    files.push_back({relative, read_file_bytes(fd, name, budget)});
    ++state.progress.entries_read;
    ++state.progress.files_read;
    state.progress.bytes_read += static_cast<std::int64_t>(files.back().bytes.size());
    state.report();
  }
  return files;
}

}  // namespace

std::vector<KiderRawFile> read_kider_archive_bytes(std::string_view bytes, const std::string& name,
                                                   const KiderReadObserver& observer,
                                                   ImportByteBudget* budget) {
  ArchivePointer reader = new_reader();
  if (archive_read_open_memory(reader.get(), bytes.data(), bytes.size()) != ARCHIVE_OK)
    throw std::runtime_error(name + ": cannot open archive: " + error_text(reader.get()));
  ImportByteBudget own_budget;
  ReadState state;
  state.budget = budget != nullptr ? budget : &own_budget;
  state.observer = &observer;
  state.outer = reader.get();
  state.progress.bytes_total = static_cast<std::int64_t>(bytes.size());
  std::vector<KiderRawFile> files;
  read_entries(reader.get(), name, "", true, state, files);
  finish_reading(state);
  std::sort(files.begin(), files.end(),
            [](const KiderRawFile& a, const KiderRawFile& b) { return a.path < b.path; });
  if (files.empty()) throw std::runtime_error(name + ": no Kider .asd.rad.txt files found");
  return files;
}

std::vector<KiderRawFile> read_kider_raw_files(const std::filesystem::path& path,
                                               const KiderReadObserver& observer,
                                               const KiderReadRules& rules) {
  ImportByteBudget own_budget;
  ImportByteBudget& budget = rules.budget != nullptr ? *rules.budget : own_budget;
  std::error_code error;
  const std::filesystem::file_status status = rules.confine_to.empty()
                                                  ? std::filesystem::status(path, error)
                                                  : std::filesystem::symlink_status(path, error);
  if (!std::filesystem::exists(status))
    throw std::runtime_error(shown(rules, path) + ": no such file or folder");
  std::vector<KiderRawFile> files = std::filesystem::is_directory(status)
                                        ? read_folder_files(path, observer, rules, budget)
                                        : read_archive_files(path, observer, rules, budget);
  std::sort(files.begin(), files.end(),
            [](const KiderRawFile& a, const KiderRawFile& b) { return a.path < b.path; });
  if (files.empty())
    throw std::runtime_error(shown(rules, path) + ": no Kider .asd.rad.txt files found");
  return files;
}

void check_readable_archive(const std::filesystem::path& file, const std::string& shown_as) {
  const FileDescriptor fd = open_regular_file(file, false, shown_as);
  if (!fd.is_open()) throw std::runtime_error(shown_as + ": not a regular file");
  ArchivePointer reader = new_reader();
  archive_entry* entry = nullptr;
  const bool opened = archive_read_open_fd(reader.get(), fd.get(), 1 << 16) == ARCHIVE_OK;
  const int first = opened ? archive_read_next_header(reader.get(), &entry) : ARCHIVE_FATAL;
  if (first != ARCHIVE_OK && first != ARCHIVE_WARN && first != ARCHIVE_EOF)
    throw std::runtime_error(
        shown_as + " is not an archive (7z, zip, tar, cpio or rar): " + error_text(reader.get()));
}

std::vector<MeasuredCapture> decode_kider_files(const std::vector<KiderRawFile>& files,
                                                const std::string& source_prefix,
                                                const KiderImportOptions& options) {
  std::map<std::string, std::vector<KiderSampleFile>> by_capture;
  for (const KiderRawFile& file : files) {
    const auto name = parse_kider_file_name(base_name_of(file.path));
    if (!name) continue;
    const std::string source = source_prefix.empty() ? file.path : source_prefix + ":" + file.path;
    std::istringstream in(file.bytes);
    by_capture[name->capture_label].push_back({source, *name, read_kider_spectrum(in, source)});
  }
  std::vector<MeasuredCapture> captures;
  for (auto& [label, capture_files] : by_capture)
    captures.push_back(assemble_kider_capture(std::move(capture_files), options));
  return captures;
}

std::vector<MeasuredCapture> read_kider_archive(const std::filesystem::path& archive_path,
                                                const KiderImportOptions& options) {
  ImportByteBudget budget;
  return decode_kider_files(read_archive_files(archive_path, {}, {}, budget), archive_path.string(),
                            options);
}

std::vector<MeasuredCapture> read_kider_folder(const std::filesystem::path& folder,
                                               const KiderImportOptions& options) {
  ImportByteBudget budget;
  return decode_kider_files(read_folder_files(folder, {}, {}, budget), folder.string(), options);
}

std::vector<MeasuredCapture> read_kider_path(const std::filesystem::path& path,
                                             const KiderImportOptions& options) {
  return decode_kider_files(read_kider_raw_files(path), path.string(), options);
}

}  // namespace clearsky::storage
