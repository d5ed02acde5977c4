// Reading Kider et al. 2014 captures from where users keep them: the published .7z archives
// (read directly with libarchive, nothing unpacked to disk), any archive libarchive reads
// holding .asd.rad.txt files or such archives one level down (e.g. a tar of the published
// .7z files), or folders of .asd.rad.txt files. Files that are not .asd.rad.txt (the archives
// also hold raw .asd.txt) are ignored. Any malformed file, truncated archive or incomplete
// capture is an error naming it; nothing is returned partially. Reading can report its
// progress (an import's job state, the CLI's progress lines).
// Every byte kept is counted against a byte budget as it is read (import_byte_budget.h): the
// sizes an archive declares are never trusted nor reserved. Only regular files are read: a
// device, fifo or socket named like a radiance file is skipped, and an archive path that is
// not a regular file is an error. Server-side imports are confined to a folder (the import root
// they resolved in): links that lead out of it are not followed (docs/data-api.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/importers/import_byte_budget.h"
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

// How an import reads: its byte budget (shared by the sources of one import; null: a budget of
// the read's own with the default limits) and, for server-side imports, the canonical folder
// the files must lie in (empty: anywhere; the path given must then be canonical, as
// api/datasets/import_roots.h resolves it, and is opened without following a link).
// shown_as names the path in messages (empty: the path itself), so that a server-side import's
// errors name the path as requested rather than where it resolved.
struct KiderReadRules {
  ImportByteBudget* budget = nullptr;
  std::filesystem::path confine_to;
  std::string shown_as;
};

// The raw bytes of every .asd.rad.txt file of an archive or folder, by path inside it (a
// nested archive's files as "inner.7z/path"), sorted by path (what an importer hashes to
// recognise content it already holds).
struct KiderRawFile {
  std::string path;
  std::string bytes;
};
std::vector<KiderRawFile> read_kider_raw_files(const std::filesystem::path& path,
                                               const KiderReadObserver& observer = {},
                                               const KiderReadRules& rules = {});

// The .asd.rad.txt files of an archive held in memory (e.g. an HTTP upload); name is used
// in messages.
std::vector<KiderRawFile> read_kider_archive_bytes(std::string_view bytes, const std::string& name,
                                                   const KiderReadObserver& observer = {},
                                                   ImportByteBudget* budget = nullptr);

// Whether a file is an archive this reader opens (7z, zip, tar, cpio, rar, compressed or
// not), from its first entry's header, before an import of it is accepted (an upload that is
// not one is refused up front). Throws std::runtime_error naming the file as shown_as, with
// libarchive's reason, otherwise.
void check_readable_archive(const std::filesystem::path& file, const std::string& shown_as);

// Decodes raw files (as read_kider_raw_files returns them) into captures; source_prefix names
// their container in messages.
std::vector<MeasuredCapture> decode_kider_files(const std::vector<KiderRawFile>& files,
                                                const std::string& source_prefix,
                                                const KiderImportOptions& options = {});

}  // namespace clearsky::storage
