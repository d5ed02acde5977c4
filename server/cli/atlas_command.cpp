// `clearsky atlas [--models all|ID,...] [--db PATH --dataset NAME] [--rmse all|standard]
// [--quick] [--threads N] [--json]`: the run-time-vs-error atlas of docs/performance.md
// (models/atlas/model_atlas.h).
// For every model, each cost setting (table resolutions, scattering orders, ray samples, sun
// buckets, wavelength grids; the study's standard setting first) is built and timed and
// compared with the model's converged reference over a fixed geometry set; with --dataset, each
// is also evaluated against the stored measured skies by the study's RMSE (the code path of
// `clearsky evaluate`). --quick: fewer settings, a coarse geometry set and a cheaper,
// unchecked reference (minutes for all models); without it, an hour or more. Progress lines go
// to stderr.
#include <iomanip>
#include <iostream>
#include <stdexcept>

#include "api/encode/atlas_json.h"
#include "api/evaluation/evaluation_runner.h"
#include "api/evaluation/prepared_dataset.h"
#include "models/atlas/model_atlas.h"
#include "models/registry.h"
#include "server/cli/commands.h"
#include "server/cli/database_option.h"

namespace clearsky::cli {

namespace {

void print_text(const atlas::ModelAtlasReport& r) {
  std::cout << r.model << " (version " << r.version << "): " << r.seconds << " s; reference "
            << r.reference.setting.name << " (" << r.reference_reason << ")\n";
  if (r.reference_check)
    std::cout << "  reference against " << r.reference_check->setting.name << ": p95 "
              << r.reference_check->spectral_error.p95 << ", max "
              << r.reference_check->spectral_error.max << '\n';
  for (const atlas::SettingMeasurement& m : r.settings) {
    std::cout << "  " << std::left << std::setw(30) << m.setting.name << std::right << " build "
              << m.build_cpu_s << " s CPU, " << m.table_bytes << " B, radiance "
              << m.radiance_s * 1e6 << " us, 81 views " << m.batch_81_s * 1e6 << " us, p95 "
              << m.spectral_error.p95 << ", max " << m.spectral_error.max;
    if (m.rmse) std::cout << ", RMSE " << *m.rmse;
    std::cout << '\n';
  }
  std::cout << "  draft: " << (r.draft.empty() ? "none" : r.draft) << '\n';
}

}  // namespace

void add_atlas_command(CLI::App& app) {
  auto* command = app.add_subcommand(
      "atlas", "Run time against error of every model's cost settings (docs/performance.md)");
  struct Options {
    std::vector<std::string> models{"all"};
    std::string db = kDefaultDatabasePath;
    std::string dataset;
    std::string rmse = "all";
    bool quick = false;
    unsigned threads = 0;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  command->add_option("--models", options->models, "all, or model ids separated by commas")
      ->delimiter(',')
      ->capture_default_str();
  add_database_option(*command, options->db);
  command->add_option("--dataset", options->dataset,
                      "Stored dataset to evaluate every setting against (the study's RMSE)");
  command
      ->add_option("--rmse", options->rmse,
                   "With --dataset: the RMSE of every setting (all) or of the standard one only "
                   "(standard: for models that spend seconds per capture's sun, Haber)")
      ->check(CLI::IsMember({"all", "standard"}))
      ->capture_default_str();
  command->add_flag("--quick", options->quick,
                    "Fewer settings, a coarse geometry set and a cheaper, unchecked reference");
  command->add_option("--threads", options->threads,
                      "Threads of each precomputation and of the evaluation (default 0: all "
                      "cores)");
  command->add_flag("--json", options->json, "Print one JSON object: {\"models\": [...]}");
  command->callback([options] {
    const std::vector<const ModelFactory*> factories =
        api::resolve_models(options->models, registered_models());
    api::PreparedDataset prepared;
    if (!options->dataset.empty()) {
      storage::Database db = open_cli_database(options->db);
      prepared = api::load_prepared_dataset(db, options->dataset);
    }
    atlas::AtlasOptions run;
    run.scope = options->quick ? atlas::AtlasScope::quick : atlas::AtlasScope::full;
    run.precompute_threads = options->threads;
    run.capture_threads = options->threads;
    run.min_timing_s = options->quick ? 0.05 : 0.2;
    run.captures = prepared.captures;
    run.rmse_of_every_setting = options->rmse == "all";
    run.log = [](const std::string& line) { std::cerr << line << std::endl; };
    nlohmann::json models = nlohmann::json::array();
    for (const ModelFactory* factory : factories) {
      const atlas::ModelAtlasReport report = atlas::model_atlas(*factory, run);
      if (options->json) {
        models.push_back(api::atlas_report_to_json(report));
      } else {
        print_text(report);
      }
    }
    if (options->json) {
      nlohmann::json out = {{"scope", options->quick ? "quick" : "full"},
                            {"dataset", options->dataset},
                            {"precompute_threads", options->threads},
                            {"models", models}};
      std::cout << out.dump(2) << '\n';
    }
  });
}

}  // namespace clearsky::cli
