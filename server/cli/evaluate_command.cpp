// `clearsky evaluate --dataset NAME [--models all|a,b] [--parameters JSON] [--out-of-domain
// exclude|clamp] [--json]
// [--samples[=spectra]] [--db PATH]`: the paper's RMSE of models against a stored dataset; every run is stored with
// its per-sample errors (api/evaluation/evaluation_runner.h). --samples adds each capture's
// per-sample RMSE and bias (=spectra: and errors per wavelength) as GET
// /v1/evaluations/{id}?samples=... does (api/encode/evaluation_json.h). --parameters is the
// "parameters" object of POST /v1/evaluations (atmosphere parameters and model options), with
// its rule: each applies to the requested models that list it, one that none lists is refused
// (docs/data-api.md "Evaluation parameters"). --out-of-domain exclude|clamp is its
// "out_of_domain" parameter: what is done with the samples a model cannot answer (docs/data-api.md
// "Samples a model cannot answer"); it overrides the same key of --parameters.
#include <cmath>
#include <iomanip>
#include <iostream>

#include "api/encode/evaluation_json.h"
#include "api/evaluation/broadband_evaluation_runner.h"
#include "api/evaluation/evaluation_fit.h"
#include "api/evaluation/evaluation_runner.h"
#include "api/evaluation/evaluations_api.h"
#include "api/http/json_body.h"
#include "models/registry.h"
#include "server/cli/aerosol_inversion_source_installed.h"
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
    std::string samples = "false";
    std::string parameters;
    std::string out_of_domain;
  };
  auto options = std::make_shared<Options>();
  command->add_option("--dataset", options->dataset, "Dataset name")->required();
  command->add_option("--models", options->models, "all, or model ids separated by commas")
      ->delimiter(',')
      ->capture_default_str();
  add_database_option(*command, options->db);
  command->add_option(
      "--parameters", options->parameters,
      "JSON object of atmosphere parameters and model options, as the \"parameters\" of "
      "POST /v1/evaluations, e.g. '{\"turbidity\": 3, \"scattering_orders\": 2}'");
  command
      ->add_option("--out-of-domain", options->out_of_domain,
                   "Samples a model cannot answer (outside its fit domain, sun or view beyond "
                   "its range): exclude them (default; counted per capture and reason) or clamp "
                   "(the model at the nearest point of its domain)")
      ->check(CLI::IsMember({"exclude", "clamp"}));
  command->add_flag("--json", options->json,
                    "Print the results as one JSON object (RMSE in mW/(m2.sr.nm))");
  command
      ->add_flag("--samples{true}", options->samples,
                 "Per-sample RMSE and bias of each capture; --samples=spectra also the "
                 "errors per wavelength (model - measured, mW/(m2.sr.nm))")
      ->check(CLI::IsMember({"true", "false", "spectra"}));
  command->callback([options, software_version] {
    storage::Database db = open_cli_database(options->db);
    const AerosolInversionSourceInstalled aerosol_source(options->db);
    api::EvaluationRequest request;
    request.dataset = options->dataset;
    request.models = options->models;
    request.software_version = software_version;
    if (!options->parameters.empty()) {
      nlohmann::json parameters;
      try {
        parameters = api::parse_client_json(options->parameters, "parameters");
      } catch (const api::ApiError& e) {
        // A member at fault is named ("alpha: ..."); the whole text is the option itself.
        throw CLI::ValidationError("--parameters",
                                   e.parameter() == "parameters" ? e.reason() : e.what());
      }
      std::vector<const ModelFactory*> factories;
      try {
        factories = api::resolve_models(request.models, registered_models());
      } catch (const std::invalid_argument& e) {
        throw CLI::ValidationError("--models", e.what());
      }
      request.parameters = api::parse_evaluation_parameters(parameters, factories);
      api::check_evaluation_fit(db, request.parameters, factories);
    }
    if (!options->out_of_domain.empty())
      request.parameters[api::kOutOfDomainParameter] = options->out_of_domain;
    if (api::is_broadband_dataset(db, request.dataset)) {
      // A broadband irradiance series: each model's GHI, DHI and DNI against it, W/m2.
      api::BroadbandEvaluationReport broadband;
      try {
        broadband = api::run_broadband_evaluation(db, request, registered_models());
      } catch (const api::ApiError& e) {
        if (e.parameter() == "models") throw CLI::ValidationError("--models", e.reason());
        throw;
      }
      if (options->json) {
        std::cout << api::broadband_evaluation_json(broadband, options->samples != "false").dump(2)
                  << '\n';
        return;
      }
      std::cout << std::fixed << std::setprecision(2);
      for (const api::BroadbandModelRun& run : broadband.models) {
        std::cout << run.model_id << ": RMSE " << run.rmse_w_m2.value_or(std::nan(""))
                  << " W/m2 over " << run.samples_sun_up << " of " << run.samples
                  << " samples with the sun up (run " << run.run_id << ", precompute "
                  << run.precompute_seconds << " s, evaluate " << run.evaluate_seconds << " s)\n";
        for (const api::BroadbandComponentResult& c : run.components)
          std::cout << "  " << c.component << ": RMSE " << c.rmse_w_m2.value_or(std::nan(""))
                    << " W/m2, mean bias " << c.mean_bias_w_m2.value_or(std::nan(""))
                    << " W/m2 over " << c.samples_compared << " samples\n";
      }
      return;
    }
    const api::EvaluationReport report = api::run_evaluation(db, request);
    const api::SampleDetail samples = options->samples == "spectra" ? api::SampleDetail::spectra
                                      : options->samples == "true"  ? api::SampleDetail::summary
                                                                    : api::SampleDetail::none;
    if (options->json) {
      std::cout << api::evaluation_to_json(report, samples).dump(2) << '\n';
      return;
    }
    std::cout << std::fixed << std::setprecision(2);
    for (const api::ModelRun& run : report.models) {
      const EvaluationResult& r = run.result;
      std::cout << r.model_id << ": RMSE " << r.rmse << " mW/(m2.sr.nm) over " << r.captures.size()
                << " captures, " << r.samples_compared << " samples (run " << run.run_id
                << ", precompute " << r.precompute_seconds << " s, evaluate " << r.evaluate_seconds
                << " s)\n";
      if (r.samples_excluded + r.samples_clamped + r.captures_unanswered > 0)
        std::cout << "  out of domain (" << to_string(report.out_of_domain)
                  << "): " << r.samples_excluded << " samples excluded, " << r.samples_clamped
                  << " clamped, " << r.captures_unanswered << " captures unanswered\n";
      for (const CaptureEvaluation& c : r.captures) {
        std::cout << "  " << c.time_iso << "  sun " << c.sun_zenith_deg << " / "
                  << c.sun_azimuth_deg << " deg  ";
        if (c.answered())
          std::cout << "RMSE " << c.rmse << " over " << c.samples.size() << " samples";
        else
          std::cout << "unanswered";
        for (const auto& [lists, what] :
             {std::pair{&c.excluded, "excluded"}, std::pair{&c.clamped, "clamped"}})
          for (const OutOfDomainSamples& l : *lists)
            std::cout << "; " << l.indices.size() << " " << what << " (" << to_string(l.reason)
                      << ")";
        std::cout << '\n';
        if (samples == api::SampleDetail::none) continue;
        for (const SampleEvaluation& s : c.samples)
          std::cout << "    sample " << std::setw(2) << s.index << "  view " << std::setw(6)
                    << s.view_zenith_deg << " / " << std::setw(6) << s.view_azimuth_deg
                    << " deg  RMSE " << std::setw(8) << s.rmse << "  bias " << std::setw(8)
                    << s.bias << '\n';
      }
    }
  });
}

}  // namespace clearsky::cli
