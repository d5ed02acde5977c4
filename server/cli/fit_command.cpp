// `clearsky fit --dataset NAME --model ID [--free a,b] [--bounds JSON] [--grid N,..]
// [--captures LABEL,..] [--parameters JSON] [--search-options JSON] [--per-capture]
// [--cross-validate] [--max-evaluations N] [--fold-evaluations N] [--quality LEVEL] [--history]
// [--json]
// [--db PATH]`: fits the model's atmosphere to a stored dataset (docs/fits.md); the fit is
// stored (the fits table) and printed as GET /v1/fits/{id} answers it (api/encode/fit_json.h).
#include <iomanip>
#include <iostream>
#include <sstream>

#include "api/encode/fit_json.h"
#include "api/error/api_error.h"
#include "api/evaluation/broadband_evaluation_runner.h"
#include "api/fits/fit_runner.h"
#include "api/http/json_body.h"
#include "models/core/invalid_input.h"
#include "server/cli/aerosol_inversion_source_installed.h"
#include "server/cli/commands.h"
#include "server/cli/database_option.h"
#include "storage/repositories/fit_repository.h"

namespace clearsky::cli {

namespace {

nlohmann::json json_option(const std::string& text, const std::string& option, const char* member) {
  try {
    return api::parse_client_json(text, member);
  } catch (const api::ApiError& e) {
    throw CLI::ValidationError(option, e.parameter() == member ? e.reason() : e.what());
  }
}

// A number of the answer with digits digits after the point; "-" for null (unanswered).
std::string number(const nlohmann::json& value, int digits) {
  if (!value.is_number()) return "-";
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << value.get<double>();
  return out.str();
}

std::string values(const nlohmann::json& named) {
  std::string out;
  for (const auto& [name, value] : named.items())
    out += (out.empty() ? "" : ", ") + name + " " + number(value, 4);
  return out;
}

// unit: of the RMSE, mW/(m2.sr.nm) for captures, W/m2 for a broadband irradiance series.
void print_text(const nlohmann::json& fit, const char* unit) {
  std::cout << "fit " << fit["id"] << ": " << fit["model"].get<std::string>() << " on "
            << fit["dataset"].get<std::string>() << ": " << values(fit["values"]) << '\n';
  std::cout << "  RMSE before " << number(fit["rmse_before"], 3) << ", after "
            << number(fit["rmse_after"], 3) << " (search setting " << number(fit["rmse_search"], 3)
            << ")";
  if (!fit["cross_validated_rmse"].is_null())
    std::cout << ", cross-validated " << number(fit["cross_validated_rmse"], 3);
  std::cout << " " << unit << "\n";
  for (const nlohmann::json& u : fit["uncertainty"])
    std::cout << "  " << u["name"].get<std::string>() << ": RMSE within 1% of the minimum for ["
              << number(u["scan"][0], 4) << ", " << number(u["scan"][1], 4) << "] (scan), ["
              << number(u["sampled"][0], 4) << ", " << number(u["sampled"][1], 4)
              << "] (points evaluated)\n";
  for (const nlohmann::json& c : fit["captures_fitted"]) {
    std::cout << "  " << c["label"].get<std::string>() << "  RMSE " << number(c["rmse_before"], 3)
              << " -> " << number(c["rmse_after"], 3);
    if (c.contains("own_values"))
      std::cout << "  alone: " << values(c["own_values"]) << " (" << number(c["own_rmse"], 3)
                << ")";
    if (c.contains("held_out_rmse")) std::cout << "  held out " << number(c["held_out_rmse"], 3);
    std::cout << '\n';
  }
  std::cout << "  " << fit["search"]["evaluations"] << " evaluations, "
            << number(fit["seconds"]["total"], 1) << " s\n";
}

}  // namespace

void add_fit_command(CLI::App& app, const std::string& software_version) {
  auto* command = app.add_subcommand(
      "fit", "Fit a model's atmosphere to a stored dataset (stored as a fit; docs/fits.md)");
  struct Options {
    std::string db = kDefaultDatabasePath;
    api::FitRequest request;
    std::string bounds;
    std::string parameters;
    std::string search_options;
    std::string quality;
    bool history = false;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  api::FitRequest& r = options->request;
  command->add_option("--dataset", r.dataset, "Dataset name")->required();
  command->add_option("--model", r.model, "Model id")->required();
  add_database_option(*command, options->db);
  command
      ->add_option("--free", r.free,
                   "Free parameters, separated by commas (default: alpha,beta,g for the "
                   "Bruneton family, else turbidity)")
      ->delimiter(',');
  command->add_option("--bounds", options->bounds,
                      "JSON object of bounds, e.g. '{\"turbidity\": [2, 6]}' (default: the "
                      "descriptor's ranges; the study's box for alpha, beta, g)");
  command->add_option("--grid", r.grid, "Grid points per free parameter, separated by commas")
      ->delimiter(',');
  command->add_option("--captures", r.captures, "Capture labels to fit (default: all)")
      ->delimiter(',');
  command->add_option("--parameters", options->parameters,
                      "JSON object of fixed parameters and options, as the \"parameters\" of "
                      "POST /v1/evaluations; a free parameter given here is the start");
  command->add_option("--search-options", options->search_options,
                      "JSON object of table options for the search (default: the cheap tables "
                      "for table models; {} searches at the standard setting)");
  command->add_flag("--per-capture", r.per_capture, "Also fit each capture alone");
  command->add_flag("--cross-validate", r.cross_validate,
                    "Leave-one-capture-out cross-validation (held-out RMSE)");
  command
      ->add_option("--max-evaluations", r.max_refine_evaluations,
                   "Refinement budget (model builds) after the grid")
      ->capture_default_str();
  command
      ->add_option("--fold-evaluations", r.max_fold_refine_evaluations,
                   "Refinement budget per capture and per fold")
      ->capture_default_str();
  command
      ->add_option("--quality", options->quality,
                   "Quality level of the model's options (draft, standard, reference; "
                   "docs/quality-levels.md); the \"quality\" of --parameters")
      ->check(CLI::IsMember({"draft", "standard", "reference"}));
  command->add_flag("--history", options->history, "With --json: every point evaluated");
  command->add_flag("--json", options->json, "Print the fit as one JSON object");
  command->callback([options, software_version] {
    api::FitRequest request = options->request;
    request.software_version = software_version;
    if (!options->bounds.empty())
      request.bounds = json_option(options->bounds, "--bounds", "bounds");
    if (!options->parameters.empty())
      request.parameters = json_option(options->parameters, "--parameters", "parameters");
    if (!options->quality.empty()) {
      if (request.parameters.is_object() && request.parameters.contains("quality"))
        throw CLI::ValidationError("--quality", "also given in --parameters");
      if (!request.parameters.is_object()) request.parameters = nlohmann::json::object();
      request.parameters["quality"] = options->quality;
    }
    if (!options->search_options.empty())
      request.search_options =
          json_option(options->search_options, "--search-options", "search_options");
    storage::Database db = open_cli_database(options->db);
    const AerosolInversionSourceInstalled aerosol_source(options->db);
    if (!options->json)
      request.progress = [last = std::string()](double fraction, std::string_view stage) mutable {
        if (stage == last) return;
        last = std::string(stage);
        std::cerr << "  " << stage << " (" << static_cast<int>(100 * fraction) << "%)\n";
      };
    std::int64_t id = 0;
    try {
      id = api::run_fit(db, request);
    } catch (const InvalidInput& e) {
      throw CLI::ValidationError("--" + e.field(), e.what());
    }
    const auto record = storage::FitRepository(db).get(id);
    const nlohmann::json fit = api::fit_to_json(*record, options->history);
    if (options->json)
      std::cout << fit.dump(2) << '\n';
    else
      print_text(fit, api::is_broadband_dataset(db, request.dataset) ? "W/m2" : "mW/(m2.sr.nm)");
  });
}

}  // namespace clearsky::cli
