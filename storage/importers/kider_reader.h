// Reading Kider et al. 2014 captures from where users keep them: the published .7z archives
// (read directly with libarchive, nothing unpacked to disk) or folders of .asd.rad.txt files.
// Files that are not .asd.rad.txt (the archives also hold raw .asd.txt) are ignored. Any
// malformed file, truncated archive or incomplete capture is an error naming it; nothing is
// returned partially.
#pragma once

#include <filesystem>
#include <string>
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

// The raw bytes of every .asd.rad.txt file of an archive or folder, by path inside it, sorted
// by path (what an importer hashes to recognise content it already holds).
struct KiderRawFile {
  std::string path;
  std::string bytes;
};
std::vector<KiderRawFile> read_kider_raw_files(const std::filesystem::path& path);

// Decodes raw files (as read_kider_raw_files returns them) into captures; source_prefix names
// their container in messages.
std::vector<MeasuredCapture> decode_kider_files(const std::vector<KiderRawFile>& files,
                                                const std::string& source_prefix,
                                                const KiderImportOptions& options = {});

}  // namespace clearsky::storage
