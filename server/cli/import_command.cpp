// `clearsky import kider PATH... [--name NAME] [--db PATH] [--json]`: imports Kider et al.
// 2014 captures (.7z archives, archives of them, or folders) into a dataset, in one
// transaction, synchronously: the importer the server's import jobs run (storage/importers/),
// with its progress printed to stderr (at most twice a second, and at each phase) unless
// --json, whose report is the API's (api/datasets/datasets_api.h).
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>

#include "api/datasets/datasets_api.h"
#include "server/cli/commands.h"
#include "server/cli/database_option.h"
#include "storage/importers/kider_importer.h"
#include "storage/repositories/dataset_name.h"

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

}  // namespace

void add_import_command(CLI::App& app) {
  auto* import = app.add_subcommand("import", "Import measured skies into a dataset");
  import->require_subcommand(1);
  auto* kider = import->add_subcommand(
      "kider",
      "Kider et al. 2014 captures: .7z archives, archives of them, or folders of .asd.rad.txt");
  struct Options {
    std::vector<std::string> paths;
    std::string name = "kider2014";
    std::string db = kDefaultDatabasePath;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  kider->add_option("paths", options->paths, "Archives (.7z, tar, zip) or folders")
      ->required()
      ->check(CLI::ExistingPath);
  kider->add_option("--name", options->name, "Dataset name")
      ->capture_default_str()
      ->check(CLI::Validator(
          [](const std::string& name) {
            return storage::is_valid_dataset_name(name)
                       ? std::string()
                       : "a dataset name is " + std::string(storage::kDatasetNameRule);
          },
          "NAME"));
  add_database_option(*kider, options->db);
  kider->add_flag("--json", options->json, "Print the import report as JSON (no progress lines)");
  kider->callback([options] {
    storage::Database db = open_cli_database(options->db);
    storage::KiderImportRequest request;
    request.dataset_name = options->name;
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
