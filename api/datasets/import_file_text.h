// The whole text of a file of an open measurement format (docs/measurement-formats.md), read
// into memory to be checked whole before anything is written (sky_radiance_import.h,
// irradiance_import.h). Held to the import's max_entry_bytes, since the file and its parsed rows
// are in memory at once (413 too_large naming max_entry_bytes).
#pragma once

#include <filesystem>
#include <string>

#include "storage/importers/import_byte_budget.h"

namespace clearsky::api {

// shown_as names the file in messages (never the server's spool path); a file that cannot be
// read is a std::runtime_error.
std::string read_import_file_text(const std::filesystem::path& file,
                                  const storage::ImportByteLimits& limits,
                                  const std::string& shown_as);

}  // namespace clearsky::api
