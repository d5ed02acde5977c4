// Datasets of measured skies: a named set of captures of one format (e.g. "kider2014"), or, of
// kind broadband_irradiance, a time series of irradiance samples (irradiance_sample_repository.h).
// SQL on the datasets table lives only here. Thread-safety: as the Database it uses.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/repositories/keyset_page.h"
#include "storage/sqlite/database.h"

namespace clearsky::storage {

// The kinds of dataset (schema version 9, docs/data-api.md "Dataset kinds").
inline constexpr std::string_view kSkyRadianceKind = "sky_radiance";
inline constexpr std::string_view kBroadbandIrradianceKind = "broadband_irradiance";

struct DatasetSummary {
  std::int64_t id = 0;
  std::string name;
  std::string format;
  std::string created_utc;
  std::int64_t captures = 0;
  std::int64_t samples = 0;
  std::string kind = std::string(kSkyRadianceKind);
  std::int64_t irradiance_samples = 0;
};

class DatasetRepository {
 public:
  explicit DatasetRepository(Database& db) : db_(db) {}
  // The dataset's id, creating it of that kind when absent; throws ImportConflict when it exists
  // with another format (a format belongs to one kind).
  std::int64_t find_or_create(const std::string& name, const std::string& format,
                              std::string_view kind = kSkyRadianceKind);
  std::optional<DatasetSummary> find(const std::string& name);
  std::vector<DatasetSummary> list();  // by name
  // At most limit datasets by name, those after after_name when given.
  KeysetPage<DatasetSummary> list_page(std::int64_t limit,
                                       const std::optional<std::string>& after_name = std::nullopt);
  // Deletes the dataset with its captures, samples and runs; false when absent.
  bool remove(const std::string& name);

 private:
  Database& db_;
};

}  // namespace clearsky::storage
