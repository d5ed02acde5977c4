// `clearsky datasets [--db PATH] [--json]`: the stored datasets with their capture and
// sample counts.
#include <iostream>

#include "api/encode/evaluation_json.h"
#include "server/cli/commands.h"
#include "server/cli/database_option.h"
#include "storage/repositories/dataset_repository.h"

namespace clearsky::cli {

void add_datasets_command(CLI::App& app) {
  auto* command = app.add_subcommand("datasets", "List the stored measurement datasets");
  struct Options {
    std::string db = kDefaultDatabasePath;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  add_database_option(*command, options->db);
  command->add_flag("--json", options->json, "Print the datasets as a JSON array");
  command->callback([options] {
    storage::Database db = open_cli_database(options->db);
    const auto datasets = storage::DatasetRepository(db).list();
    if (options->json) {
      std::cout << api::datasets_to_json(datasets).dump(2) << '\n';
      return;
    }
    for (const auto& d : datasets)
      std::cout << d.name << "\t" << d.format << "\t" << d.captures << " captures\t" << d.samples
                << " samples\n";
  });
}

}  // namespace clearsky::cli
