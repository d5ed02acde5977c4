// The `clearsky` subcommands. Each add_*_command registers its options on app and the action
// to run when it is chosen; each lives in its own file under server/cli/.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace clearsky::cli {

void add_models_command(CLI::App& app);
void add_serve_command(CLI::App& app, const std::string& software_version);
void add_sun_command(CLI::App& app);
void add_import_command(CLI::App& app);
void add_datasets_command(CLI::App& app);
void add_evaluate_command(CLI::App& app, const std::string& software_version);
void add_fit_command(CLI::App& app, const std::string& software_version);
void add_stress_command(CLI::App& app);
void add_atlas_command(CLI::App& app);

}  // namespace clearsky::cli
