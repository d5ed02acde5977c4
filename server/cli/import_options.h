// The options the `clearsky import` subcommands share (docs/architecture.md "Command line"): the
// dataset imported into (--name, --db) and, for the Kider archives and pyranometer records, the
// site and clock of the files (--lat, --lon, --elevation, --utc-offset: the parameters of
// api/datasets/import_site_clock.h, read by the same parser as the HTTP import's).
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <optional>
#include <string>

#include "server/cli/database_option.h"
#include "storage/importers/kider_format.h"

namespace clearsky::cli {

struct ImportDatasetOptions {
  std::string name;
  std::string db = kDefaultDatabasePath;
};

// --name and --db. Without default_name --name is required (the command checks it when it runs,
// api::check_dataset_name); with one it is optional and its value checked as it is parsed.
void add_import_dataset_options(CLI::App& command, ImportDatasetOptions& options,
                                const std::optional<std::string>& default_name = std::nullopt);

// The site and clock options as given, by parameter name (lat, lon, elevation, utc_offset).
using ImportSiteClockOptions = std::map<std::string, std::string>;

// --lat, --lon, --elevation and --utc-offset; clock_description says what the offset is of.
void add_import_site_clock_options(CLI::App& command, ImportSiteClockOptions& given,
                                   const std::string& clock_description);

// The site and clock given (each default where not): a CLI::ValidationError naming the option
// out of range. command names the command in messages ("clearsky import kider").
storage::KiderImportOptions parse_import_site_clock_options(const ImportSiteClockOptions& given,
                                                            const std::string& command);

}  // namespace clearsky::cli
