// Kider captures from .7z archives (libarchive) and folders (kider_reader.h).
#include "storage/importers/kider_reader.h"

#include <archive.h>
#include <archive_entry.h>

#include <algorithm>
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

bool is_radiance_file(const std::string& path) { return parse_kider_file_name(base_name_of(path)).has_value(); }

std::vector<KiderRawFile> read_archive_files(const std::filesystem::path& path) {
  std::unique_ptr<archive, ArchiveDeleter> reader(archive_read_new());
  if (!reader) throw std::runtime_error("libarchive: out of memory");
  archive_read_support_filter_all(reader.get());
  archive_read_support_format_all(reader.get());
  const std::string name = path.string();
  if (archive_read_open_filename(reader.get(), name.c_str(), 1 << 16) != ARCHIVE_OK)
    throw std::runtime_error(name + ": cannot open archive: " + error_text(reader.get()));
  std::vector<KiderRawFile> files;
  archive_entry* entry = nullptr;
  for (;;) {
    const int status = archive_read_next_header(reader.get(), &entry);
    if (status == ARCHIVE_EOF) break;
    if (status != ARCHIVE_OK && status != ARCHIVE_WARN)
      throw std::runtime_error(name + ": corrupt or truncated archive: " + error_text(reader.get()));
    if (archive_entry_filetype(entry) != AE_IFREG) continue;
    const char* entry_path = archive_entry_pathname(entry);
    const std::string inner = entry_path ? entry_path : "";
    if (!is_radiance_file(inner)) continue;
    std::string bytes;
    if (archive_entry_size_is_set(entry)) bytes.reserve(static_cast<std::size_t>(archive_entry_size(entry)));
    char buffer[1 << 16];
    for (;;) {
      const la_ssize_t n = archive_read_data(reader.get(), buffer, sizeof buffer);
      if (n == 0) break;
      if (n < 0)
        throw std::runtime_error(name + ": " + inner + ": corrupt or truncated archive: " +
                                 error_text(reader.get()));
      bytes.append(buffer, static_cast<std::size_t>(n));
    }
    if (archive_entry_size_is_set(entry) && bytes.size() != static_cast<std::size_t>(archive_entry_size(entry)))
      throw std::runtime_error(name + ": " + inner + ": truncated archive entry");
    files.push_back({inner, std::move(bytes)});
  }
  return files;
}

std::vector<KiderRawFile> read_folder_files(const std::filesystem::path& folder) {
  std::vector<KiderRawFile> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    const std::string relative = std::filesystem::relative(entry.path(), folder).generic_string();
    if (!is_radiance_file(relative)) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    if (!in) throw std::runtime_error(entry.path().string() + ": cannot open");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (in.bad()) throw std::runtime_error(entry.path().string() + ": read error");
    files.push_back({relative, std::move(bytes).str()});
  }
  return files;
}

}  // namespace

std::vector<KiderRawFile> read_kider_raw_files(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error(path.string() + ": no such file or folder");
  std::vector<KiderRawFile> files =
      std::filesystem::is_directory(path) ? read_folder_files(path) : read_archive_files(path);
  std::sort(files.begin(), files.end(), [](const KiderRawFile& a, const KiderRawFile& b) { return a.path < b.path; });
  if (files.empty()) throw std::runtime_error(path.string() + ": no Kider .asd.rad.txt files found");
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
  return decode_kider_files(read_archive_files(archive_path), archive_path.string(), options);
}

std::vector<MeasuredCapture> read_kider_folder(const std::filesystem::path& folder, const KiderImportOptions& options) {
  return decode_kider_files(read_folder_files(folder), folder.string(), options);
}

std::vector<MeasuredCapture> read_kider_path(const std::filesystem::path& path, const KiderImportOptions& options) {
  return decode_kider_files(read_kider_raw_files(path), path.string(), options);
}

}  // namespace clearsky::storage
