// The options the import subcommands share (import_options.h).
#include "server/cli/import_options.h"

#include <algorithm>
#include <utility>

#include "api/datasets/import_site_clock.h"
#include "api/error/api_error.h"
#include "storage/repositories/dataset_name.h"

namespace clearsky::cli {

void add_import_dataset_options(CLI::App& command, ImportDatasetOptions& options,
                                const std::optional<std::string>& default_name) {
  if (default_name) {
    options.name = *default_name;
    command.add_option("--name", options.name, "Dataset name")
        ->capture_default_str()
        ->check(CLI::Validator(
            [](const std::string& name) {
              return storage::is_valid_dataset_name(name)
                         ? std::string()
                         : "a dataset name is " + std::string(storage::kDatasetNameRule);
            },
            "NAME"));
  } else {
    command.add_option("--name", options.name, "Dataset name")->required();
  }
  add_database_option(command, options.db);
}

void add_import_site_clock_options(CLI::App& command, ImportSiteClockOptions& given,
                                   const std::string& clock_description) {
  for (const auto& [name, what] :
       {std::pair<std::string, std::string>{"lat",
                                            "Site latitude, North positive (default: "
                                            "the published captures' site, Cornell)"},
        {"lon", "Site longitude, East positive (default: Cornell)"},
        {"elevation", "Site elevation above sea level, m (default: 250)"},
        {"utc-offset", clock_description + " (default: -04:00)"}}) {
    const std::string parameter = name == "utc-offset" ? "utc_offset" : name;
    command.add_option_function<std::string>(
        "--" + name, [&given, parameter](const std::string& value) { given[parameter] = value; },
        what);
  }
}

storage::KiderImportOptions parse_import_site_clock_options(const ImportSiteClockOptions& given,
                                                            const std::string& command) {
  api::Parameters site_clock(command);
  for (const auto& [name, value] : given) site_clock.add(name, value);
  try {
    return api::parse_import_site_clock(site_clock);
  } catch (const api::ApiError& e) {
    std::string option = "--" + e.parameter();
    std::replace(option.begin(), option.end(), '_', '-');
    throw CLI::ValidationError(option, e.reason());
  }
}

}  // namespace clearsky::cli
