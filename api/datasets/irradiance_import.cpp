// Import of broadband irradiance (irradiance_import.h).
#include "api/datasets/irradiance_import.h"

#include <chrono>

#include "api/datasets/import_file_text.h"
#include "api/datasets/import_format.h"
#include "api/datasets/irradiance_csv.h"
#include "api/datasets/irradiance_json.h"
#include "api/error/api_error.h"
#include "models/evaluation/measured_sky.h"
#include "storage/importers/import_conflict.h"
#include "storage/repositories/dataset_repository.h"

namespace clearsky::api {

std::vector<storage::IrradianceSample> read_irradiance_file(const std::filesystem::path& file,
                                                            std::string_view format,
                                                            const storage::ImportByteLimits& limits,
                                                            const std::string& shown_as) {
  const std::string text = read_import_file_text(file, limits, shown_as);
  return format == kIrradianceJsonFormat ? parse_irradiance_json(text) : parse_irradiance_csv(text);
}

nlohmann::ordered_json import_irradiance_samples(
    storage::Database& db, const std::string& dataset, std::string_view dataset_format,
    const std::vector<storage::IrradianceSample>& samples) {
  const auto start = std::chrono::steady_clock::now();
  storage::Transaction transaction(db);
  std::int64_t dataset_id = 0;
  try {
    dataset_id = storage::DatasetRepository(db).find_or_create(dataset, std::string(dataset_format),
                                                               storage::kBroadbandIrradianceKind);
  } catch (const storage::ImportConflict& e) {
    throw ApiError(409, "conflict", "name", e.what());
  }
  const std::int64_t added = storage::IrradianceSampleRepository(db).insert(dataset_id, samples);
  transaction.commit();
  nlohmann::ordered_json report = {
      {"dataset", dataset},
      {"kind", storage::kBroadbandIrradianceKind},
      {"samples_added", added},
      {"samples_unchanged", static_cast<std::int64_t>(samples.size()) - added}};
  if (!samples.empty()) {
    const auto [first, last] = std::minmax_element(
        samples.begin(), samples.end(),
        [](const auto& a, const auto& b) { return a.time_utc_s < b.time_utc_s; });
    report["first_time"] = local_time_iso8601(first->time_utc_s, first->utc_offset_minutes);
    report["last_time"] = local_time_iso8601(last->time_utc_s, last->utc_offset_minutes);
  }
  report["seconds"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace clearsky::api
