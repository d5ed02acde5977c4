// Import of the open sky-radiance format (sky_radiance_import.h).
#include "api/datasets/sky_radiance_import.h"

#include <chrono>

#include "api/datasets/import_file_text.h"
#include "api/datasets/import_format.h"
#include "api/datasets/sky_radiance_csv.h"
#include "api/datasets/sky_radiance_json.h"

namespace clearsky::api {

std::vector<MeasuredCapture> read_sky_radiance_file(const std::filesystem::path& file,
                                                    std::string_view format,
                                                    const storage::ImportByteLimits& limits,
                                                    const std::string& shown_as) {
  const std::string text = read_import_file_text(file, limits, shown_as);
  return format == kSkyRadianceJsonFormat ? parse_sky_radiance_json(text)
                                          : parse_sky_radiance_csv(text);
}

storage::ImportReport import_sky_radiance(
    storage::Database& db, const std::string& dataset, const std::filesystem::path& file,
    std::string_view format, const storage::ImportByteLimits& limits, const std::string& shown_as,
    const std::function<void(const storage::ImportProgress&)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<storage::DecodedCaptures> decoded(1);
  decoded[0].source = shown_as;
  decoded[0].captures = read_sky_radiance_file(file, format, limits, shown_as);
  storage::ImportProgress read;
  std::error_code error;
  read.bytes_read = static_cast<std::int64_t>(std::filesystem::file_size(file, error));
  read.bytes_total = read.bytes_read;
  read.entries_read = read.entries_total = read.files_read = 1;
  storage::CaptureWrite write;
  write.dataset_name = dataset;
  write.dataset_format = std::string(kSkyRadianceDatasetFormat);
  write.progress = progress;
  storage::ImportReport report = storage::write_captures(db, decoded, write, read);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace clearsky::api
