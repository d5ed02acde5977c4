// `clearsky import kider PATH... [--name NAME] [--db PATH] [--json] [--lat DEG] [--lon DEG]
// [--elevation M] [--utc-offset +hh:mm]`: imports Kider et al. 2014 captures (.7z archives, archives of them, or folders) into a dataset, in one
// transaction, synchronously: the importer the server's import jobs run (storage/importers/),
// with its progress printed to stderr (at most twice a second, and at each phase) unless
// --json, whose report is the API's (api/datasets/datasets_api.h).
#include <chrono>
#include <filesystem>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>

#include "api/datasets/datasets_api.h"
#include "api/datasets/import_format.h"
#include "api/datasets/irradiance_import.h"
#include "api/datasets/sky_radiance_import.h"
#include "server/cli/commands.h"
#include "server/cli/database_option.h"
#include "server/cli/import_options.h"
#include "storage/importers/kider_importer.h"
#include "storage/importers/kider_pyranometer.h"

namespace clearsky::cli {

namespace {

std::string megabytes(std::int64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / 1e6);
  return text;
}

// One progress line; totals only when known.
void print_progress(const storage::ImportProgress& p) {
  std::cerr << "import: " << p.phase << ": " << p.entries_read;
  if (p.entries_total >= 0) std::cerr << " of " << p.entries_total;
  std::cerr << " entries, " << megabytes(p.bytes_read);
  if (p.bytes_total >= 0) std::cerr << " of " << megabytes(p.bytes_total);
  std::cerr << ", " << p.files_read << " files; " << p.captures_added << " captures ("
            << p.samples_added << " samples) added\n";
}

// The files of an open format, CSV or JSON by their extension (docs/measurement-formats.md).
void add_open_format_files(CLI::App& command, std::vector<std::string>& files) {
  command.add_option("files", files, "CSV (.csv) or JSON (.json) files")
      ->required()
      ->check(CLI::ExistingFile);
}

std::string_view open_format_of(const std::string& file, std::string_view csv_format,
                                std::string_view json_format) {
  const std::string extension = std::filesystem::path(file).extension().string();
  if (extension != ".csv" && extension != ".json")
    throw CLI::ValidationError("files", file + ": neither .csv nor .json");
  return extension == ".csv" ? csv_format : json_format;
}

// The operator's own files: no import limits beyond the machine's.
storage::ImportByteLimits operator_file_limits() {
  storage::ImportByteLimits limits;
  limits.max_entry_bytes = limits.max_import_bytes = std::numeric_limits<std::int64_t>::max();
  return limits;
}

// `clearsky import sky-radiance FILE... [--name NAME] [--db PATH] [--json]`: files of the open
// format (docs/measurement-formats.md), CSV or JSON by their extension, in one transaction each.
void add_sky_radiance_import(CLI::App& import) {
  auto* command = import.add_subcommand(
      "sky-radiance", "Files of the open sky-radiance format (.csv or .json), checked whole");
  struct Options {
    std::vector<std::string> files;
    ImportDatasetOptions dataset;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  add_open_format_files(*command, options->files);
  add_import_dataset_options(*command, options->dataset);
  command->add_flag("--json", options->json, "Print the import reports as JSON");
  command->callback([options] {
    api::check_dataset_name(options->dataset.name);
    storage::Database db = open_cli_database(options->dataset.db);
    for (const std::string& file : options->files) {
      const std::string_view format =
          open_format_of(file, api::kSkyRadianceCsvFormat, api::kSkyRadianceJsonFormat);
      const storage::ImportReport report = api::import_sky_radiance(
          db, options->dataset.name, file, format, operator_file_limits(), file);
      if (options->json) {
        std::cout << api::import_report_json(report).dump(2) << '\n';
        continue;
      }
      std::cout << "dataset " << report.dataset << ": " << file << ": " << report.added.size()
                << " captures added (" << report.samples_added << " samples), "
                << report.unchanged.size() << " already present\n";
    }
  });
}

// `clearsky import irradiance FILE... --name NAME [--db PATH]`: files of the open broadband
// irradiance format (docs/measurement-formats.md "Broadband irradiance"), CSV or JSON by their
// extension, in one transaction each; the report is the API's, as JSON.
void add_irradiance_import(CLI::App& import) {
  auto* command = import.add_subcommand(
      "irradiance", "Files of the open broadband irradiance format (.csv or .json), checked whole");
  struct Options {
    std::vector<std::string> files;
    ImportDatasetOptions dataset;
  };
  auto options = std::make_shared<Options>();
  add_open_format_files(*command, options->files);
  add_import_dataset_options(*command, options->dataset);
  command->callback([options] {
    api::check_dataset_name(options->dataset.name);
    storage::Database db = open_cli_database(options->dataset.db);
    for (const std::string& file : options->files) {
      const std::string_view format =
          open_format_of(file, api::kIrradianceCsvFormat, api::kIrradianceJsonFormat);
      std::cout << api::import_irradiance_samples(
                       db, options->dataset.name, api::kIrradianceDatasetFormat,
                       api::read_irradiance_file(file, format, operator_file_limits(), file))
                       .dump(2)
                << '\n';
    }
  });
}

// `clearsky import pyranometer PATH... --name NAME [--lat --lon --elevation --utc-offset]
// [--first-record LOCAL_TIME] [--db PATH]`: the Kider et al. 2014 pyranometer records
// (storage/importers/kider_pyranometer.h), per-capture files, the day file, or folders of them,
// at the site and on the clock given as for `import kider`.
void add_pyranometer_import(CLI::App& import) {
  auto* command = import.add_subcommand(
      "pyranometer",
      "Kider et al. 2014 pyranometer records (YYYY.MM.DD.HH.MM.SS.txt, pyranometer_full_day.txt)");
  struct Options {
    std::vector<std::string> paths;
    ImportDatasetOptions dataset;
    std::optional<std::string> first_record;
    ImportSiteClockOptions site_clock;
  };
  auto options = std::make_shared<Options>();
  command->add_option("paths", options->paths, "Record files or folders")
      ->required()
      ->check(CLI::ExistingPath);
  add_import_dataset_options(*command, options->dataset);
  command->add_option_function<std::string>(
      "--first-record", [options](const std::string& value) { options->first_record = value; },
      "Local time of the day file's first record, YYYY-MM-DDThh:mm:ss (default: the earliest "
      "per-capture record given with it)");
  add_import_site_clock_options(*command, options->site_clock, "UTC offset of the records' clock");
  command->callback([options] {
    api::check_dataset_name(options->dataset.name);
    const storage::KiderImportOptions clock =
        parse_import_site_clock_options(options->site_clock, "clearsky import pyranometer");
    std::vector<std::filesystem::path> paths(options->paths.begin(), options->paths.end());
    storage::KiderPyranometerRead read;
    try {
      read = storage::read_kider_pyranometer(paths, clock, options->first_record);
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError("paths", e.what());
    }
    storage::Database db = open_cli_database(options->dataset.db);
    nlohmann::ordered_json report = api::import_irradiance_samples(
        db, options->dataset.name, api::kKiderPyranometerDatasetFormat, read.samples);
    report["notes"] = read.notes;
    std::cout << report.dump(2) << '\n';
  });
}

}  // namespace

void add_import_command(CLI::App& app) {
  auto* import = app.add_subcommand("import", "Import measured skies into a dataset");
  import->require_subcommand(1);
  auto* kider = import->add_subcommand(
      "kider",
      "Kider et al. 2014 captures: .7z archives, archives of them, or folders of .asd.rad.txt");
  struct Options {
    std::vector<std::string> paths;
    ImportDatasetOptions dataset;
    bool json = false;
    // The site and clock of the archives (api/datasets/import_site_clock.h), as given.
    ImportSiteClockOptions site_clock;
  };
  auto options = std::make_shared<Options>();
  kider->add_option("paths", options->paths, "Archives (.7z, tar, zip) or folders")
      ->required()
      ->check(CLI::ExistingPath);
  add_import_dataset_options(*kider, options->dataset, "kider2014");
  add_import_site_clock_options(*kider, options->site_clock,
                                "UTC offset of the file names' local time");
  kider->add_flag("--json", options->json, "Print the import report as JSON (no progress lines)");
  add_sky_radiance_import(*import);
  add_irradiance_import(*import);
  add_pyranometer_import(*import);
  kider->callback([options] {
    storage::Database db = open_cli_database(options->dataset.db);
    storage::KiderImportRequest request;
    request.dataset_name = options->dataset.name;
    request.options = parse_import_site_clock_options(options->site_clock, "clearsky import kider");
    for (const auto& p : options->paths) request.paths.emplace_back(p);
    if (!options->json) {
      using Clock = std::chrono::steady_clock;
      auto last_line = std::make_shared<Clock::time_point>();
      auto last_phase = std::make_shared<std::string>();
      request.progress = [last_line, last_phase](const storage::ImportProgress& p) {
        const auto now = Clock::now();
        if (p.phase == *last_phase && now - *last_line < std::chrono::milliseconds(500)) return;
        *last_line = now;
        *last_phase = p.phase;
        print_progress(p);
      };
    }
    const storage::ImportReport report = storage::import_kider(db, request);
    if (options->json) {
      std::cout << api::import_report_json(report).dump(2) << '\n';
      return;
    }
    std::cout << "dataset " << report.dataset << ": " << report.added.size() << " captures added ("
              << report.samples_added << " samples), " << report.unchanged.size()
              << " already present, in " << report.seconds << " s\n";
  });
}

}  // namespace clearsky::cli
