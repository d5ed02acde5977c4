// Fitting a model's atmosphere to measured skies (docs/fits.md): the values of the free
// parameters (fit_space.h) that minimise the evaluation's RMSE over the captures
// (fit_objective.h), with honest error bars.
//  1. Coarse grid: every point of the grid over the bounds (the study's 11 x 10 x 5 over alpha,
//     beta, g for the Bruneton family; Bruneton 2016, section "Quantitative evaluations").
//  2. Refinement from the best grid point with NLopt's BOBYQA (Powell 2009, "The BOBYQA
//     algorithm for bound constrained optimization without derivatives"; Nelder-Mead with
//     bounds for a single parameter), derivative-free and inside the bounds, until the values
//     move less than relative_tolerance of the bounds' width or max_refine_evaluations.
//  3. Uncertainty: per free parameter, the range within which the RMSE stays within
//     uncertainty_fraction (1%) of the minimum, (a) along a 1-D scan through the optimum (the
//     others held at the optimum; bisection to 1/2^scan_bisections of the bound's distance)
//     and (b) over every point evaluated (grid, refinement, scans, folds).
//  4. Optional: per capture, the values that fit that capture alone (how they move over the
//     day); leave-one-capture-out cross-validation, the fit refined on all captures but one
//     and the RMSE of the held-out capture at the fold's optimum (the figure to quote).
// Table models (Bruneton, Elek) build new tables at every point: the search (grid, refinement,
// scans, folds) runs with search_options (cheap tables, fit_space.h cheap_search_options)
// applied over config's options and on the config's wavelengths that the evaluation compares
// (31 of the paper's 40 bins), and the optimum is then evaluated at config's own setting
// (rmse_after, per-capture after); rmse_search is the RMSE the search saw at the optimum.
// Thread-safety: fit_model may run on several threads at once for different fits.
#pragma once

#include <atomic>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "models/core/sky_model.h"
#include "models/evaluation/evaluate_model.h"
#include "models/fitting/fit_objective.h"
#include "models/fitting/fit_space.h"

namespace clearsky {

struct FitSettings {
  std::vector<FreeParameter> parameters;  // make_free_parameters
  ModelConfig config;  // the fixed parameters and the standard setting; the start ("before")
  // Options applied over config's during the search (cheap tables); empty: search at config.
  std::map<std::string, double> search_options;
  EvaluationOptions evaluation;  // as the evaluation's (out_of_domain, wavelengths)
  int max_refine_evaluations = 200;
  int max_fold_refine_evaluations = 60;  // per capture and per fold
  double relative_tolerance = 1e-4;      // of each bound's width
  double uncertainty_fraction = 0.01;
  int scan_bisections = 7;
  bool per_capture = false;
  bool cross_validate = false;
  // Told the fraction done (0..1) and the stage ("grid", "refine", "scan", "per_capture",
  // "cross_validate", "confirm").
  std::function<void(double fraction, std::string_view stage)> progress;
  const std::atomic<bool>* cancel = nullptr;  // PrecomputeCancelled when set
};

struct ParameterUncertainty {
  std::string name;
  double value = 0;
  double scan_low = 0, scan_high = 0;        // 1-D scan through the optimum
  double sampled_low = 0, sampled_high = 0;  // every point evaluated
};

struct CaptureFit {
  std::string label;
  double rmse_before = 0;  // at config (NaN: unanswered)
  double rmse_after = 0;   // at the fit's values, config's setting
  // --per-capture: the values fitting this capture alone and its RMSE there (search setting).
  std::vector<double> own_values;
  double own_rmse = 0;
  // --cross-validate: the fold without this capture: its values and this capture's RMSE there.
  std::vector<double> fold_values;
  double held_out_rmse = 0;
};

struct FitResult {
  std::string model_id;
  std::string model_version;
  std::vector<FreeParameter> parameters;
  std::vector<double> initial_values;  // the free parameters in config (NaN: albedo "grass")
  std::vector<double> grid_values;     // the best grid point
  double grid_rmse = 0;
  std::vector<double> values;  // the optimum
  double rmse_before = 0;      // config's values and setting
  double rmse_search = 0;      // the optimum at the search setting
  double rmse_after = 0;       // the optimum at config's setting
  bool search_setting_differs = false;
  std::map<std::string, double> search_options;  // what the search ran with
  std::string refine_algorithm;                  // e.g. "LN_BOBYQA"
  std::string refine_stop;                       // NLopt's reason, e.g. "XTOL_REACHED"
  std::vector<ParameterUncertainty> uncertainty;
  std::vector<CaptureFit> captures;
  std::optional<double> cross_validated_rmse;  // sqrt(mean held_out_rmse^2)
  std::vector<FitSample> history;              // every point the search evaluated
  std::size_t grid_evaluations = 0;
  std::size_t refine_evaluations = 0;
  // Wall seconds per stage.
  std::map<std::string, double> seconds;
};

// Fits the model to the prepared captures. Throws std::invalid_argument when no capture is given
// or the model answers none at the start, whatever evaluate_model throws, and PrecomputeCancelled.
FitResult fit_model(const ModelFactory& factory, std::span<const MeasuredCapture> captures,
                    const FitSettings& settings);

}  // namespace clearsky
