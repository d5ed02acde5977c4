// `clearsky evaluate --dataset NAME [--models all|a,b] [--json] [--db PATH]`: the paper's RMSE
// of models against a stored dataset; every run is stored (api/evaluation/evaluation_runner.h).
#include <iomanip>
#include <iostream>

#include "api/encode/evaluation_json.h"
#include "api/evaluation/evaluation_runner.h"
#include "server/cli/commands.h"
#include "server/cli/database_option.h"

namespace clearsky::cli {

void add_evaluate_command(CLI::App& app, const std::string& software_version) {
  auto* command =
      app.add_subcommand("evaluate", "RMSE of models against a stored dataset (stored as runs)");
  struct Options {
    std::string dataset;
    std::vector<std::string> models{"all"};
    std::string db = kDefaultDatabasePath;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  command->add_option("--dataset", options->dataset, "Dataset name")->required();
  command->add_option("--models", options->models, "all, or model ids separated by commas")
      ->delimiter(',')
      ->capture_default_str();
  add_database_option(*command, options->db);
  command->add_flag("--json", options->json, "Print the results as JSON (DESIGN.md CLI contract)");
  command->callback([options, software_version] {
    storage::Database db = open_cli_database(options->db);
    api::EvaluationRequest request;
    request.dataset = options->dataset;
    request.models = options->models;
    request.software_version = software_version;
    const api::EvaluationReport report = api::run_evaluation(db, request);
    if (options->json) {
      std::cout << api::evaluation_to_json(report).dump(2) << '\n';
      return;
    }
    std::cout << std::fixed << std::setprecision(2);
    for (const api::ModelRun& run : report.models) {
      const EvaluationResult& r = run.result;
      std::cout << r.model_id << ": RMSE " << r.rmse << " mW/(m2.sr.nm) over " << r.captures.size()
                << " captures (run " << run.run_id << ", precompute " << r.precompute_seconds
                << " s, evaluate " << r.evaluate_seconds << " s)\n";
      for (const CaptureEvaluation& c : r.captures)
        std::cout << "  " << c.time_iso << "  sun " << c.sun_zenith_deg << " / "
                  << c.sun_azimuth_deg << " deg  RMSE " << c.rmse << '\n';
    }
  });
}

}  // namespace clearsky::cli
