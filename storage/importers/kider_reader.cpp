// Kider captures from .7z archives (libarchive) and folders (kider_reader.h).
#include "storage/importers/kider_reader.h"

#include <archive.h>
#include <archive_entry.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

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

ArchivePointer new_reader() {
  ArchivePointer reader(archive_read_new());
  if (!reader) throw std::runtime_error("libarchive: out of memory");
  archive_read_support_filter_all(reader.get());
  archive_read_support_format_all(reader.get());
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

std::string read_entry_bytes(archive* reader, archive_entry* entry, const std::string& name,
                             const std::string& inner) {
  std::string bytes;
  if (archive_entry_size_is_set(entry))
    bytes.reserve(static_cast<std::size_t>(archive_entry_size(entry)));
  char buffer[1 << 16];
  for (;;) {
    const la_ssize_t n = archive_read_data(reader, buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0)
      throw std::runtime_error(name + ": " + inner +
                               ": corrupt or truncated archive: " + error_text(reader));
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
      files.push_back({prefix + inner, read_entry_bytes(reader, entry, name, inner)});
      ++state.progress.files_read;
    } else if (nested && is_nested_archive(inner)) {
      const std::string bytes = read_entry_bytes(reader, entry, name, inner);
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

std::vector<KiderRawFile> read_archive_files(const std::filesystem::path& path,
                                             const KiderReadObserver& observer) {
  ArchivePointer reader = new_reader();
  const std::string name = path.string();
  if (archive_read_open_filename(reader.get(), name.c_str(), 1 << 16) != ARCHIVE_OK)
    throw std::runtime_error(name + ": cannot open archive: " + error_text(reader.get()));
  ReadState state;
  state.observer = &observer;
  state.outer = reader.get();
  std::error_code error;
  const auto size = std::filesystem::file_size(path, error);
  if (!error) state.progress.bytes_total = static_cast<std::int64_t>(size);
  std::vector<KiderRawFile> files;
  read_entries(reader.get(), name, "", true, state, files);
  finish_reading(state);
  return files;
}

std::vector<KiderRawFile> read_folder_files(const std::filesystem::path& folder,
                                            const KiderReadObserver& observer) {
  // Listed first so that progress has totals.
  std::vector<std::filesystem::path> radiance;
  ReadState state;
  state.observer = &observer;
  state.progress.bytes_total = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    if (!is_radiance_file(entry.path().filename().string())) continue;
    radiance.push_back(entry.path());
    state.progress.bytes_total += static_cast<std::int64_t>(entry.file_size());
  }
  state.progress.entries_total = static_cast<std::int64_t>(radiance.size());
  std::vector<KiderRawFile> files;
  for (const std::filesystem::path& path : radiance) {
    const std::string relative = std::filesystem::relative(path, folder).generic_string();
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path.string() + ": cannot open");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (in.bad()) throw std::runtime_error(path.string() + ": read error");
    files.push_back({relative, std::move(bytes).str()});
    ++state.progress.entries_read;
    ++state.progress.files_read;
    state.progress.bytes_read += static_cast<std::int64_t>(files.back().bytes.size());
    state.report();
  }
  return files;
}

}  // namespace

std::vector<KiderRawFile> read_kider_archive_bytes(std::string_view bytes, const std::string& name,
                                                   const KiderReadObserver& observer) {
  ArchivePointer reader = new_reader();
  if (archive_read_open_memory(reader.get(), bytes.data(), bytes.size()) != ARCHIVE_OK)
    throw std::runtime_error(name + ": cannot open archive: " + error_text(reader.get()));
  ReadState state;
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
                                               const KiderReadObserver& observer) {
  if (!std::filesystem::exists(path))
    throw std::runtime_error(path.string() + ": no such file or folder");
  std::vector<KiderRawFile> files = std::filesystem::is_directory(path)
                                        ? read_folder_files(path, observer)
                                        : read_archive_files(path, observer);
  std::sort(files.begin(), files.end(),
            [](const KiderRawFile& a, const KiderRawFile& b) { return a.path < b.path; });
  if (files.empty())
    throw std::runtime_error(path.string() + ": no Kider .asd.rad.txt files found");
  return files;
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
  return decode_kider_files(read_archive_files(archive_path, {}), archive_path.string(), options);
}

std::vector<MeasuredCapture> read_kider_folder(const std::filesystem::path& folder,
                                               const KiderImportOptions& options) {
  return decode_kider_files(read_folder_files(folder, {}), folder.string(), options);
}

std::vector<MeasuredCapture> read_kider_path(const std::filesystem::path& path,
                                             const KiderImportOptions& options) {
  return decode_kider_files(read_kider_raw_files(path), path.string(), options);
}

}  // namespace clearsky::storage
