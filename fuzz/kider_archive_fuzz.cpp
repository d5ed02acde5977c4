// The Kider importer (storage/importers/) on archive bytes: whatever libarchive reads (7z, zip,
// tar, compressed or not, archives one level down), as an upload reaches it. The radiance
// files found are decoded, then written to a folder and read back as a folder import, and an
// archive that holds a whole capture is imported into a fresh SQLite database, all as the
// server's import jobs do (docs/fuzzing.md).
//
// Invariants: every refusal is a std::exception naming the source (nothing else escapes, no
// sanitizer report); a decoded capture has the 81 samples in scan order, finite radiance and
// directions within the sky; the folder reading of the same files decodes the same captures;
// an imported capture is reported added once.
#include <cmath>
#include <cstdint>
#include <fstream>
#include <set>
#include <string>

#include "fuzz/support/fuzz_check.h"
#include "fuzz/support/scratch_dir.h"
#include "storage/importers/kider_importer.h"
#include "storage/importers/kider_reader.h"
#include "storage/schema/migrations.h"

// libarchive's 7-Zip reader allocates buffers of the sizes an archive's header declares before
// it reads them: a forged 6 KB header made it calloc 3.4 GB (docs/fuzzing.md, finding 8). glibc
// maps such a block lazily, so the server's resident memory stays small (measured: 20 MB, and
// the upload is a 400 invalid_archive), but libFuzzer reports any single allocation above its
// limit. Allocations above 256 MB return null here instead, which libarchive turns into an
// error the importer refuses, as it would under an address-space limit (RLIMIT_AS).
extern "C" const char* __asan_default_options() {
  return "allocator_may_return_null=1:max_allocation_size_mb=256";
}

namespace clearsky::fuzz {
namespace {

constexpr double kPi = 3.14159265358979323846;

void check_captures(const std::vector<MeasuredCapture>& captures, const std::string& where) {
  for (const MeasuredCapture& c : captures) {
    check(c.samples.size() == storage::kKiderSampleCount, where + ": capture without 81 samples");
    check(std::isfinite(c.unix_time_utc_s), where + ": non-finite capture time");
    for (std::size_t i = 0; i < c.samples.size(); ++i) {
      const MeasuredSample& s = c.samples[i];
      check(s.index == static_cast<int>(i), where + ": samples out of scan order");
      check(s.view.zenith_rad >= 0 && s.view.zenith_rad <= kPi / 2,
            where + ": view zenith outside [0, 90] deg");
      check(s.view.azimuth_rad >= 0 && s.view.azimuth_rad < 2 * kPi,
            where + ": view azimuth outside [0, 360) deg");
      for (const double w : s.radiance.wavelengths_nm())
        check(std::isfinite(w), where + ": non-finite wavelength");
      for (const double v : s.radiance.values())
        check(std::isfinite(v), where + ": non-finite radiance");
    }
  }
}

// The files as a folder on disk (base names only, as a user would unpack them), read back.
std::vector<MeasuredCapture> read_as_folder(const std::vector<storage::KiderRawFile>& files,
                                            const std::filesystem::path& folder) {
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  for (const storage::KiderRawFile& f : files) {
    const std::string name = std::filesystem::path(f.path).filename().string();
    if (name.empty() || name == "." || name == "..") continue;
    std::ofstream(folder / name, std::ios::binary) << f.bytes;
  }
  return storage::read_kider_folder(folder);
}

}  // namespace
}  // namespace clearsky::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace clearsky;
  using namespace clearsky::fuzz;
  static ScratchDir scratch("kider_archive");
  const std::string bytes(reinterpret_cast<const char*>(data), size);

  std::vector<storage::KiderRawFile> files;
  std::vector<MeasuredCapture> captures;
  try {
    files = storage::read_kider_archive_bytes(bytes, "upload.bin");
    captures = storage::decode_kider_files(files, "upload.bin");
  } catch (const std::exception&) {
    return 0;  // a refusal
  }
  check_captures(captures, "archive");
  if (files.empty()) return 0;

  // Duplicate base names in different folders of the archive collapse on disk: compared only
  // when every base name is distinct.
  std::set<std::string> names;
  for (const auto& f : files) names.insert(std::filesystem::path(f.path).filename().string());
  if (names.size() == files.size()) {
    try {
      const std::vector<MeasuredCapture> from_folder =
          read_as_folder(files, scratch.path / "folder");
      check_captures(from_folder, "folder");
      check(from_folder.size() == captures.size(), "folder and archive differ in captures");
      for (std::size_t i = 0; i < captures.size(); ++i)
        check(storage::capture_content_hash(from_folder[i]) ==
                  storage::capture_content_hash(captures[i]),
              "folder and archive decode different captures");
    } catch (const std::exception& e) {
      // The archive's files decoded: the same files in a folder must too.
      if (!captures.empty()) fail(std::string("folder refused what the archive gave: ") + e.what());
    }
  }

  if (captures.empty()) return 0;
  const std::filesystem::path db_path = scratch.path / "import.db";
  for (const char* suffix : {"", "-wal", "-shm"})
    std::filesystem::remove(db_path.string() + suffix);
  storage::Database db = storage::open_database(db_path);
  storage::KiderImportRequest request;
  request.dataset_name = "fuzz";
  request.archives_in_memory.push_back({"upload.bin", bytes});
  try {
    const storage::ImportReport report = storage::import_kider(db, request);
    check(report.added.size() == captures.size(), "import added another number of captures");
    const storage::ImportReport again = storage::import_kider(db, request);
    check(again.added.empty() && again.unchanged.size() == captures.size(),
          "re-importing the same archive changed something");
  } catch (const std::exception& e) {
    fail(std::string("import refused an archive whose captures decode: ") + e.what());
  }
  return 0;
}
