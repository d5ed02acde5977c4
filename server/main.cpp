// The clearsky executable: one CLI (CLI11) whose subcommands are in server/cli/. Errors in a
// command are reported as "clearsky: <message>" with exit status 1 (2 for usage errors).
#include <exception>
#include <iostream>

#include "server/cli/commands.h"

int main(int argc, char** argv) {
  CLI::App app{"clearsky: spectral radiance, irradiance and colour of the clear sky"};
  app.set_version_flag("--version", std::string("clearsky ") + CLEARSKY_VERSION);
  app.require_subcommand(1);
  clearsky::cli::add_models_command(app);
  clearsky::cli::add_serve_command(app, CLEARSKY_VERSION);
  clearsky::cli::add_sun_command(app);
  clearsky::cli::add_import_command(app);
  clearsky::cli::add_datasets_command(app);
  clearsky::cli::add_evaluate_command(app, CLEARSKY_VERSION);
  clearsky::cli::add_fit_command(app, CLEARSKY_VERSION);
  clearsky::cli::add_stress_command(app);
  clearsky::cli::add_atlas_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "clearsky: " << e.what() << '\n';
    return 1;
  } catch (...) {
    std::cerr << "clearsky: unknown error\n";
    return 1;
  }
  return 0;
}
