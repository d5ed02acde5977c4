// Test helper: writes a zip (libarchive, deflate) holding entries of zero bytes, streamed in
// 1 MiB pieces so that the test itself never holds an entry in memory. An entry of hundreds of
// MiB of zeros deflates to a few hundred KiB: the shape of a decompression bomb, used to check
// that imports count the bytes they read (storage/importers/import_byte_budget.h).
#pragma once

#include <archive.h>
#include <archive_entry.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace clearsky::testing {

// entries: (path inside the zip, size in bytes).
inline void write_zero_filled_zip(
    const std::filesystem::path& path,
    const std::vector<std::pair<std::string, std::int64_t>>& entries) {
  archive* writer = archive_write_new();
  archive_write_set_format_zip(writer);
  archive_write_zip_set_compression_deflate(writer);
  if (archive_write_open_filename(writer, path.c_str()) != ARCHIVE_OK) {
    archive_write_free(writer);
    throw std::runtime_error("cannot write " + path.string());
  }
  const std::string zeros(std::size_t{1} << 20, '\0');
  for (const auto& [name, size] : entries) {
    archive_entry* entry = archive_entry_new();
    archive_entry_set_pathname(entry, name.c_str());
    archive_entry_set_size(entry, size);
    archive_entry_set_filetype(entry, AE_IFREG);
    archive_entry_set_perm(entry, 0644);
    if (archive_write_header(writer, entry) != ARCHIVE_OK) {
      archive_entry_free(entry);
      archive_write_free(writer);
      throw std::runtime_error("cannot write a zip entry header");
    }
    for (std::int64_t left = size; left > 0;) {
      const auto n = static_cast<std::size_t>(std::min<std::int64_t>(left, zeros.size()));
      if (archive_write_data(writer, zeros.data(), n) != static_cast<la_ssize_t>(n)) {
        archive_entry_free(entry);
        archive_write_free(writer);
        throw std::runtime_error("cannot write zip data");
      }
      left -= static_cast<std::int64_t>(n);
    }
    archive_entry_free(entry);
  }
  archive_write_close(writer);
  archive_write_free(writer);
}

// The bytes of such a zip (through a file in dir), for uploads whose content only has to be an
// archive (the import route checks that before it accepts one).
inline std::string zero_filled_zip_bytes(
    const std::filesystem::path& dir,
    const std::vector<std::pair<std::string, std::int64_t>>& entries) {
  const std::filesystem::path path = dir / "zero_filled.zip";
  write_zero_filled_zip(path, entries);
  std::string bytes(std::filesystem::file_size(path), '\0');
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) throw std::runtime_error("cannot read " + path.string());
  const std::size_t read = std::fread(bytes.data(), 1, bytes.size(), file);
  std::fclose(file);
  if (read != bytes.size()) throw std::runtime_error("cannot read " + path.string());
  std::filesystem::remove(path);
  return bytes;
}

// A file name the Kider reader takes for a radiance file (kider_format.h), for index i.
// Appended piece by piece: GCC 12 warns falsely (-Warray-bounds, GCC bug 105651) on the
// inlined operator+ of a literal and a std::string.
inline std::string kider_radiance_name(int i) {
  std::string name = "2013-05-27___12.00.00/2013-05-27___12.00.00_-_";
  name += std::to_string(i);
  name += "____0.0___12.1151.asd.rad.txt";
  return name;
}

}  // namespace clearsky::testing
