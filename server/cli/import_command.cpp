// `clearsky import kider PATH... [--name NAME] [--db PATH] [--json]`: imports Kider et al.
// 2014 captures (.7z archives or folders) into a dataset, in one transaction.
#include <iostream>
#include <nlohmann/json.hpp>

#include "server/cli/commands.h"
#include "server/cli/database_option.h"
#include "storage/importers/kider_importer.h"

namespace clearsky::cli {

void add_import_command(CLI::App& app) {
  auto* import = app.add_subcommand("import", "Import measured skies into a dataset");
  import->require_subcommand(1);
  auto* kider = import->add_subcommand(
      "kider", "Kider et al. 2014 captures: .7z archives or folders of .asd.rad.txt");
  struct Options {
    std::vector<std::string> paths;
    std::string name = "kider2014";
    std::string db = kDefaultDatabasePath;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  kider->add_option("paths", options->paths, "Archives (.7z) or folders")
      ->required()
      ->check(CLI::ExistingPath);
  kider->add_option("--name", options->name, "Dataset name")->capture_default_str();
  add_database_option(*kider, options->db);
  kider->add_flag("--json", options->json, "Print the import report as JSON");
  kider->callback([options] {
    storage::Database db = open_cli_database(options->db);
    storage::KiderImportRequest request;
    request.dataset_name = options->name;
    for (const auto& p : options->paths) request.paths.emplace_back(p);
    const storage::ImportReport report = storage::import_kider(db, request);
    if (options->json) {
      std::cout << nlohmann::json{{"dataset", report.dataset},
                                  {"added", report.added},
                                  {"unchanged", report.unchanged},
                                  {"samples_added", report.samples_added},
                                  {"seconds", report.seconds}}
                       .dump(2)
                << '\n';
      return;
    }
    std::cout << "dataset " << report.dataset << ": " << report.added.size() << " captures added ("
              << report.samples_added << " samples), " << report.unchanged.size()
              << " already present, in " << report.seconds << " s\n";
  });
}

}  // namespace clearsky::cli
