// Import of a file of the open sky-radiance format (docs/measurement-formats.md) into a
// dataset of format "sky-radiance": read whole and checked in memory, so held to the import's
// max_entry_bytes (413 too_large naming it; measured 2026-11-27: a 42.9 MB CSV of 698,000 rows
// took the server from 21 MB to 297 MB resident while it was checked and imported), checked whole (sky_radiance_csv.h, sky_radiance_json.h: 400
// invalid_body naming the member and row), then written in one transaction
// (storage/importers/capture_writer.h). The HTTP upload calls read_sky_radiance_file before it
// answers 202, so that a malformed file is refused up front.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "models/evaluation/measured_sky.h"
#include "storage/importers/capture_writer.h"
#include "storage/importers/import_byte_budget.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

// The format of the datasets the open format is imported into.
inline constexpr std::string_view kSkyRadianceDatasetFormat = "sky-radiance";

// format: sky-radiance-csv or sky-radiance-json (import_format.h). shown_as names the file in
// messages (never the server's spool path).
std::vector<MeasuredCapture> read_sky_radiance_file(const std::filesystem::path& file,
                                                    std::string_view format,
                                                    const storage::ImportByteLimits& limits,
                                                    const std::string& shown_as);

storage::ImportReport import_sky_radiance(
    storage::Database& db, const std::string& dataset, const std::filesystem::path& file,
    std::string_view format, const storage::ImportByteLimits& limits, const std::string& shown_as,
    const std::function<void(const storage::ImportProgress&)>& progress = {});

}  // namespace clearsky::api
