// Loading of the public Kider captures for tests (public_captures.h): the archives are read
// and decoded in parallel, one per task.
#include "tests/support/public_captures.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <stdexcept>

#include "models/core/parallel.h"
#include "models/evaluation/capture_preparation.h"
#include "storage/importers/kider_reader.h"
#include "tests/support/shared_data.h"

namespace clearsky::testing {
namespace {

struct Loaded {
  std::vector<MeasuredCapture> imported;
  std::vector<MeasuredCapture> prepared;
  PublicCapturesTiming timing;
};

const Loaded& loaded() {
  static const Loaded data = [] {
    Loaded result;
    const auto folder = shared_data_dir() / "kider2014" / "2013-05-27" / "RADIANCE";
    if (!std::filesystem::is_directory(folder))
      throw std::runtime_error("public captures: no folder " + folder.string());
    std::vector<std::filesystem::path> archives;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.path().extension() == ".7z") archives.push_back(entry.path());
    std::sort(archives.begin(), archives.end());

    const auto start = std::chrono::steady_clock::now();
    std::vector<std::vector<MeasuredCapture>> per_archive(archives.size());
    parallel_for(archives.size(), [&](std::size_t i) { per_archive[i] = storage::read_kider_archive(archives[i]); });
    for (auto& captures : per_archive)
      for (auto& capture : captures) result.imported.push_back(std::move(capture));
    const auto imported = std::chrono::steady_clock::now();
    result.prepared = result.imported;
    parallel_for(result.prepared.size(), [&](std::size_t i) { prepare_capture(result.prepared[i]); });
    const auto prepared = std::chrono::steady_clock::now();
    result.timing.import_seconds = std::chrono::duration<double>(imported - start).count();
    result.timing.prepare_seconds = std::chrono::duration<double>(prepared - imported).count();
    return result;
  }();
  return data;
}

}  // namespace

const std::vector<MeasuredCapture>& public_captures() { return loaded().prepared; }
const std::vector<MeasuredCapture>& public_captures_as_imported() { return loaded().imported; }
PublicCapturesTiming public_captures_timing() { return loaded().timing; }

}  // namespace clearsky::testing
