// `clearsky models [--json]`: the registered models and their descriptors.
#include <iostream>

#include "api/encode/model_json.h"
#include "models/registry.h"
#include "server/cli/commands.h"

namespace clearsky::cli {

void add_models_command(CLI::App& app) {
  auto* command =
      app.add_subcommand("models", "List the registered sky models and their descriptors");
  auto json = std::make_shared<bool>(false);
  command->add_flag("--json", *json, "Print the descriptors as a JSON array");
  command->callback([json] {
    if (*json) {
      nlohmann::json out = nlohmann::json::array();
      for (const ModelFactory& factory : registered_models())
        out.push_back(api::descriptor_to_json(*factory.descriptor));
      std::cout << out.dump(2) << '\n';
      return;
    }
    for (const ModelFactory& factory : registered_models()) {
      const ModelDescriptor& d = *factory.descriptor;
      std::cout << d.id << "\t" << d.name << " (version " << d.version << ")\t" << d.citation
                << '\n';
    }
  });
}

}  // namespace clearsky::cli
