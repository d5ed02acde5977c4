// Reading Kider et al. 2014 captures from where users keep them: the published .7z archives
// (read directly with libarchive, nothing unpacked to disk), any archive libarchive reads
// holding .asd.rad.txt files or such archives one level down (e.g. a tar of the published
// .7z files), or folders of .asd.rad.txt files. Files that are not .asd.rad.txt (the archives
// also hold raw .asd.txt) are ignored. Any malformed file, truncated archive or incomplete
// capture is an error naming it; nothing is returned partially. Reading can report its
// progress (an import's job state, the CLI's progress lines).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/importers/kider_format.h"

namespace clearsky::storage {

// Every capture in the archive (one per DATE___HH.MM.SS), ordered by label.
std::vector<MeasuredCapture> read_kider_archive(const std::filesystem::path& archive,
                                                const KiderImportOptions& options = {});
// Every capture whose files lie in the folder or its subfolders, ordered by label.
std::vector<MeasuredCapture> read_kider_folder(const std::filesystem::path& folder,
                                               const KiderImportOptions& options = {});
// A folder or an archive (any format libarchive reads).
std::vector<MeasuredCapture> read_kider_path(const std::filesystem::path& path,
                                             const KiderImportOptions& options = {});

// How far reading one archive or folder has come. Bytes are those of the archive file as
// stored (compressed), or the sizes of a folder's radiance files; entries are archive members
// (those of nested archives included) or a folder's files. -1: not known (an archive's entry
// count is only known at its end).
struct KiderReadProgress {
  std::int64_t bytes_read = 0;
  std::int64_t bytes_total = -1;
  std::int64_t entries_read = 0;
  std::int64_t entries_total = -1;
  std::int64_t files_read = 0;  // .asd.rad.txt files
};
// Called on the reading thread after each entry (and once at the end).
using KiderReadObserver = std::function<void(const KiderReadProgress&)>;

// The raw bytes of every .asd.rad.txt file of an archive or folder, by path inside it (a
// nested archive's files as "inner.7z/path"), sorted by path (what an importer hashes to
// recognise content it already holds).
struct KiderRawFile {
  std::string path;
  std::string bytes;
};
std::vector<KiderRawFile> read_kider_raw_files(const std::filesystem::path& path,
                                               const KiderReadObserver& observer = {});

// The .asd.rad.txt files of an archive held in memory (e.g. an HTTP upload); name is used
// in messages.
std::vector<KiderRawFile> read_kider_archive_bytes(std::string_view bytes, const std::string& name,
                                                   const KiderReadObserver& observer = {});

// Decodes raw files (as read_kider_raw_files returns them) into captures; source_prefix names
// their container in messages.
std::vector<MeasuredCapture> decode_kider_files(const std::vector<KiderRawFile>& files,
                                                const std::string& source_prefix,
                                                const KiderImportOptions& options = {});

}  // namespace clearsky::storage
