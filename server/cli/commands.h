// The `clearsky` subcommands. Each add_*_command registers its options on app and the action
// to run when it is chosen; each lives in its own file under server/cli/.
#pragma once

#include <CLI/CLI.hpp>

namespace clearsky::cli {

void add_models_command(CLI::App& app);
void add_sun_command(CLI::App& app);

}  // namespace clearsky::cli
