// `clearsky stress [--models all|ID,...] [--samples N] [--parameter-values N] [--options JSON]
// [--quality LEVEL] [--threads N] [--dense-sun-sweep] [--sweeps NAME,...] [--json]`: the
// numerical stress run of docs/stability.md, dense sweeps over each model's declared domain
// (models/stress/model_stress.h). --samples N thins every sweep to at most N points and sweeps
// each parameter through min(N, 7) values (at least 2; --parameter-values sets it); without it
// every step is computed (minutes per model: a benchmark). --options gives option values of the base configuration
// (e.g. smaller tables), applied to the models that list them; --quality builds each model at
// that level's options (docs/quality-levels.md), which --options override. Exit status 1 when a model
// delivered a non-finite or negative value, refused an input its descriptor declares it
// answers, or failed a symmetry, energy or trend check.
#include <algorithm>
#include <iostream>
#include <stdexcept>

#include "api/encode/stress_json.h"
#include "api/evaluation/evaluation_runner.h"
#include "models/quality/quality_levels.h"
#include "models/registry.h"
#include "models/stress/documented_limits.h"
#include "models/stress/model_stress.h"
#include "server/cli/commands.h"

namespace clearsky::cli {

namespace {

void print_text(const stress::ModelStressReport& r) {
  std::cout << r.model << " (version " << r.version << "): " << r.samples << " samples, "
            << r.models_built << " builds, " << r.seconds << " s\n";
  for (const auto& [status, tally] : r.refusals)
    std::cout << "  refused " << to_string(status) << ": " << tally.declared << " declared, "
              << tally.undeclared << " undeclared"
              << (tally.undeclared > 0 ? " (first at " + tally.first_undeclared_at + ")" : "")
              << '\n';
  std::cout << "  non-finite values " << r.non_finite_values << ", negative values "
            << r.negative_values << '\n';
  for (const stress::SweepSummary& s : r.sweeps) {
    std::cout << "  sweep " << s.name << ": " << s.points << " points, worst jump "
              << s.worst_relative_jump << " between " << s.worst_from << " and " << s.worst_to
              << " (" << s.worst_chain << ", " << s.worst_wavelength_nm << " nm)";
    for (const stress::ExcludedJump& e : s.excluded)
      std::cout << "; documented " << e.name << " " << e.relative_jump;
    std::cout << '\n';
  }
  std::vector<const stress::BoundCheck*> checks = {&r.symmetry, &r.energy, &r.radiance_below_sun};
  for (const stress::BoundCheck& t : r.trends) checks.push_back(&t);
  for (const stress::BoundCheck* c : checks) {
    std::cout << "  " << c->name << ": " << c->violations << " of " << c->checked
              << " violations, worst " << c->worst << " at " << c->worst_at;
    if (c->violations > 0) std::cout << ", first at " << c->first_violation_at;
    if (!c->documented_limit.empty())
      std::cout << " [documented limit " << c->documented_limit << ", allowed worst "
                << c->allowed_worst << "]";
    std::cout << (stress::failed(*c) ? " FAILED" : "") << '\n';
  }
}

}  // namespace

void add_stress_command(CLI::App& app) {
  auto* command = app.add_subcommand(
      "stress", "Numerical stress run of models over their whole declared domain");
  struct Options {
    std::vector<std::string> models{"all"};
    std::size_t samples = 0;
    std::size_t parameter_values = 0;
    std::string options;
    std::string quality = "standard";
    unsigned threads = 0;
    bool dense_sun_sweep = false;
    std::vector<std::string> sweeps;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  command->add_option("--models", options->models, "all, or model ids separated by commas")
      ->delimiter(',')
      ->capture_default_str();
  command
      ->add_option("--samples", options->samples,
                   "At most N points per sweep and min(N, 7) values per parameter (default: "
                   "every step, minutes per model)")
      ->check(CLI::Range(std::size_t{2}, std::size_t{1000000}));
  command
      ->add_option("--parameter-values", options->parameter_values,
                   "Values per parameter sweep, minimum to maximum (default 7, or min(N, 7) "
                   "with --samples N; models that precompute per sun use at most 3)")
      ->check(CLI::Range(std::size_t{2}, std::size_t{1000}));
  command->add_option("--options", options->options,
                      "JSON object of option values for the base configuration, applied to "
                      "the models that list them, e.g. '{\"table_mu_size\": 32}'");
  command
      ->add_option("--quality", options->quality,
                   "Quality level of the base configuration (docs/quality-levels.md); --options "
                   "override its values")
      ->check(CLI::IsMember({"draft", "standard", "reference"}))
      ->capture_default_str();
  command->add_option("--threads", options->threads,
                      "Threads of each precomputation (default 0: all cores)");
  command->add_flag("--dense-sun-sweep", options->dense_sun_sweep,
                    "Models that precompute per sun (Haber, Nishita96) also sweep the sun "
                    "zenith every 0.05 degree over the whole range (one state per step: hours)");
  command
      ->add_option("--sweeps", options->sweeps, "Sweeps to run, separated by commas (default: all)")
      ->delimiter(',')
      ->check(
          CLI::IsMember({"sun_zenith", "view_zenith", "view_azimuth", "altitude", "parameters"}));
  command->add_flag("--json", options->json, "Print one JSON object: {\"models\": [...]}");
  command->callback([options] {
    stress::StressOptions run;
    run.max_points_per_sweep = options->samples;
    if (options->samples != 0)
      run.parameter_values = std::max<std::size_t>(2, std::min<std::size_t>(options->samples, 7));
    if (options->parameter_values != 0) run.parameter_values = options->parameter_values;
    run.precompute_threads = options->threads;
    run.dense_per_sun_zeniths = options->dense_sun_sweep;
    run.sweeps.insert(options->sweeps.begin(), options->sweeps.end());
    if (!options->options.empty()) {
      const nlohmann::json parsed = nlohmann::json::parse(options->options, nullptr, false);
      if (!parsed.is_object())
        throw std::invalid_argument("--options must be a JSON object of numbers");
      for (const auto& [name, value] : parsed.items()) {
        if (!value.is_number())
          throw std::invalid_argument("--options: " + name + " must be a number");
        run.options[name] = value.get<double>();
      }
    }
    nlohmann::json models = nlohmann::json::array();
    bool all_passed = true;
    for (const ModelFactory* factory : api::resolve_models(options->models, registered_models())) {
      stress::StressOptions model_run = run;
      apply_quality_level(
          *factory->descriptor,
          quality_setting(factory->descriptor->id, *parse_quality_level(options->quality)),
          model_run.options);
      const stress::ModelStressReport report = stress::stress_model(*factory, model_run);
      all_passed = all_passed && stress::stress_passed(report);
      if (options->json) {
        models.push_back(api::stress_report_to_json(report));
      } else {
        print_text(report);
      }
    }
    if (options->json) std::cout << nlohmann::json{{"models", models}}.dump(2) << '\n';
    if (!all_passed) throw std::runtime_error("stress checks failed (see the report)");
  });
}

}  // namespace clearsky::cli
