// Import of broadband irradiance (docs/measurement-formats.md "Broadband irradiance") into a
// dataset of kind broadband_irradiance: a file of the open format (irradiance-csv or
// irradiance-json, read whole and checked in memory, so held to the import's max_entry_bytes:
// 413 too_large naming it; refusals 400 invalid_body naming the member, irradiance_rows.h), or
// samples already read (the Kider pyranometer records, storage/importers/kider_pyranometer.h),
// written in one transaction. The HTTP upload calls read_irradiance_file before it answers 202,
// so that a malformed file is refused up front.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "storage/importers/import_byte_budget.h"
#include "storage/repositories/irradiance_sample_repository.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

// The format of the datasets the open irradiance format is imported into, and of those of the
// Kider pyranometer records.
inline constexpr std::string_view kIrradianceDatasetFormat = "irradiance";
inline constexpr std::string_view kKiderPyranometerDatasetFormat = "kider-pyranometer";

// format: irradiance-csv or irradiance-json (import_format.h). shown_as names the file in
// messages (never the server's spool path).
std::vector<storage::IrradianceSample> read_irradiance_file(const std::filesystem::path& file,
                                                            std::string_view format,
                                                            const storage::ImportByteLimits& limits,
                                                            const std::string& shown_as);

// Writes the samples into the dataset (created of kind broadband_irradiance with dataset_format
// when absent; 409 conflict when it exists with another format) in one transaction. The report
// (the import's `report`): {"dataset", "kind", "samples_added", "samples_unchanged",
// "first_time", "last_time", "seconds"}; a sample identical to one held is unchanged.
nlohmann::ordered_json import_irradiance_samples(
    storage::Database& db, const std::string& dataset, std::string_view dataset_format,
    const std::vector<storage::IrradianceSample>& samples);

}  // namespace clearsky::api
