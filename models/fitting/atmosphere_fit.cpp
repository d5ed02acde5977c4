// Fitting a model's atmosphere to measured skies (atmosphere_fit.h).
#include "models/fitting/atmosphere_fit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <nlopt.hpp>
#include <stdexcept>

#include "models/core/precompute_context.h"
#include "models/spectral/wavelength_grid.h"

namespace clearsky {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// What the optimiser sees where no capture is answered: far above any RMSE.
constexpr double kUnansweredObjective = 1e12;

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The grid's wavelengths the evaluation compares (evaluate_model.h: those in [min, max]), as a
// grid of the same kind: a table model computes each wavelength on its own (Bruneton 2016,
// section "Bruneton Model": the 2008 method run per wavelength), so the search builds tables
// for these alone (31 of the paper's 40 bins) and finds the same RMSE.
WavelengthGrid compared_wavelengths(const WavelengthGrid& grid, double min_nm, double max_nm) {
  std::vector<double> kept;
  for (double nm : grid.nanometres())
    if (nm >= min_nm && nm <= max_nm) kept.push_back(nm);
  if (kept.empty() || kept.size() == grid.size()) return grid;
  if (grid.kind() == WavelengthGrid::Kind::bins)
    return WavelengthGrid::bins(kept.front(), grid.bin_width_nm(), kept.size());
  return WavelengthGrid::points(std::move(kept));
}

struct Refined {
  std::vector<double> values;
  double rmse = kNaN;
  std::string stop;
  std::size_t evaluations = 0;
};

class Search {
 public:
  Search(FitObjective& objective, const FitSettings& settings)
      : objective_(objective), settings_(settings) {}

  void check_cancelled() const {
    if (settings_.cancel != nullptr && settings_.cancel->load(std::memory_order_relaxed))
      throw PrecomputeCancelled();
  }

  double rmse(std::span<const double> values, const std::vector<bool>& mask,
              const std::string& stage) {
    check_cancelled();
    return FitObjective::combined_rmse(objective_.capture_rmse(values, stage), mask);
  }

  // The grid point with the least RMSE under mask (grid already evaluated: no new builds).
  std::pair<std::vector<double>, double> best_of(const std::vector<std::vector<double>>& points,
                                                 const std::vector<bool>& mask) {
    std::vector<double> best;
    double best_rmse = std::numeric_limits<double>::infinity();
    for (const std::vector<double>& p : points) {
      const double r = rmse(p, mask, "grid");
      if (r < best_rmse) {
        best_rmse = r;
        best = p;
      }
    }
    if (best.empty()) best = points.front();
    return {best, best_rmse};
  }

  static std::string algorithm_name(std::size_t n) {
    return n == 1 ? "LN_NELDERMEAD" : "LN_BOBYQA";
  }

  // NLopt from start, inside the bounds; the best point seen is kept whatever NLopt returns.
  Refined refine(std::vector<double> start, const std::vector<bool>& mask, int max_evaluations,
                 const std::string& stage) {
    const std::vector<FreeParameter>& parameters = objective_.parameters();
    const std::size_t n = parameters.size();
    Refined out{start, rmse(start, mask, stage), "", 0};
    if (max_evaluations <= 0) {
      out.stop = "NO_BUDGET";
      return out;
    }
    nlopt::opt opt(n == 1 ? nlopt::LN_NELDERMEAD : nlopt::LN_BOBYQA, static_cast<unsigned>(n));
    std::vector<double> low(n), high(n), step(n), xtol(n);
    for (std::size_t i = 0; i < n; ++i) {
      const FreeParameter& p = parameters[i];
      low[i] = p.min_value;
      high[i] = p.max_value;
      const double width = p.max_value - p.min_value;
      // Half a grid step: the optimum lies within one step of the best grid point.
      step[i] = std::max(width / (2.0 * std::max(1, p.grid_points - 1)), 1e-9);
      xtol[i] = std::max(width * settings_.relative_tolerance, 1e-12);
    }
    opt.set_lower_bounds(low);
    opt.set_upper_bounds(high);
    opt.set_initial_step(step);
    opt.set_xtol_abs(xtol);
    opt.set_maxeval(max_evaluations);
    std::exception_ptr failure;
    struct Context {
      Search* search;
      const std::vector<bool>* mask;
      const std::string* stage;
      Refined* out;
      std::exception_ptr* failure;
    } context{this, &mask, &stage, &out, &failure};
    opt.set_min_objective(
        [](const std::vector<double>& x, std::vector<double>&, void* data) -> double {
          auto& c = *static_cast<Context*>(data);
          try {
            ++c.out->evaluations;
            const double r = c.search->rmse(x, *c.mask, *c.stage);
            if (std::isnan(r)) return kUnansweredObjective;
            if (std::isnan(c.out->rmse) || r < c.out->rmse) {
              c.out->rmse = r;
              c.out->values = x;
            }
            return r;
          } catch (...) {
            *c.failure = std::current_exception();
            throw nlopt::forced_stop();
          }
        },
        &context);
    std::vector<double> x = start;
    double f = 0;
    try {
      const nlopt::result result = opt.optimize(x, f);
      out.stop = nlopt_result_to_string(static_cast<nlopt_result>(result));
    } catch (const nlopt::roundoff_limited&) {
      out.stop = "ROUNDOFF_LIMITED";
    } catch (const nlopt::forced_stop&) {
      if (failure) std::rethrow_exception(failure);
      throw;
    }
    if (failure) std::rethrow_exception(failure);
    return out;
  }

  // The end of the range along parameter i from the optimum towards bound, within threshold.
  double scan(const std::vector<double>& optimum, std::size_t i, double bound, double threshold,
              const std::vector<bool>& mask) {
    std::vector<double> x = optimum;
    x[i] = bound;
    const double at_bound = rmse(x, mask, "scan");
    if (at_bound <= threshold) return bound;
    double inside = optimum[i];
    double outside = bound;
    for (int k = 0; k < settings_.scan_bisections; ++k) {
      x[i] = 0.5 * (inside + outside);
      if (rmse(x, mask, "scan") <= threshold)
        inside = x[i];
      else
        outside = x[i];
    }
    return inside;
  }

 private:
  FitObjective& objective_;
  const FitSettings& settings_;
};

}  // namespace

FitResult fit_model(const ModelFactory& factory, std::span<const MeasuredCapture> captures,
                    const FitSettings& settings) {
  if (captures.empty()) throw std::invalid_argument("a fit needs at least one capture");
  if (settings.parameters.empty()) throw std::invalid_argument("a fit needs a free parameter");
  const auto start_all = Clock::now();
  const ModelDescriptor& descriptor = *factory.descriptor;
  const std::vector<FreeParameter>& parameters = settings.parameters;
  const std::size_t n = parameters.size();
  const std::size_t capture_count = captures.size();

  FitResult result;
  result.model_id = descriptor.id;
  result.model_version = descriptor.version;
  result.parameters = parameters;
  result.search_options = settings.search_options;
  result.refine_algorithm = Search::algorithm_name(n);
  for (const FreeParameter& p : parameters)
    result.initial_values.push_back(value_in(descriptor, settings.config, p));

  EvaluationOptions options = settings.evaluation;
  options.context.cancel = settings.cancel;
  ModelConfig search_config = settings.config;
  for (const auto& [name, value] : settings.search_options) {
    const auto it = search_config.options.find(name);
    if (it == search_config.options.end() || it->second != value) {
      result.search_setting_differs = true;
      search_config.options[name] = value;
    }
  }
  if (result.search_setting_differs)
    search_config.wavelengths = compared_wavelengths(
        settings.config.wavelengths, options.min_wavelength_nm, options.max_wavelength_nm);
  FitObjective objective(factory, search_config, parameters, captures, options);
  Search search(objective, settings);
  const auto report = [&](double fraction, std::string_view stage) {
    if (settings.progress) settings.progress(fraction, stage);
  };
  const std::vector<bool> all(capture_count, true);

  // Before: the configuration as given, at its own setting.
  auto stage_start = Clock::now();
  report(0.0, "before");
  const EvaluationResult before = evaluate_model(factory, settings.config, captures, options);
  result.rmse_before = before.rmse;
  result.captures.resize(capture_count);
  for (std::size_t k = 0; k < capture_count; ++k) {
    result.captures[k].label = captures[k].label;
    result.captures[k].rmse_before = before.captures[k].answered() ? before.captures[k].rmse : kNaN;
  }
  result.seconds["before"] = seconds_since(stage_start);

  // 1. The coarse grid.
  stage_start = Clock::now();
  const std::vector<std::vector<double>> grid = grid_points(parameters);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    search.rmse(grid[i], all, "grid");
    report(0.5 * static_cast<double>(i + 1) / static_cast<double>(grid.size()), "grid");
  }
  auto [grid_best, grid_rmse] = search.best_of(grid, all);
  if (std::isinf(grid_rmse))
    throw std::invalid_argument("the model answers no capture anywhere on the grid");
  result.grid_values = grid_best;
  result.grid_rmse = grid_rmse;
  result.grid_evaluations = objective.evaluations();
  result.seconds["grid"] = seconds_since(stage_start);

  // 2. Refinement.
  stage_start = Clock::now();
  report(0.5, "refine");
  const Refined refined = search.refine(grid_best, all, settings.max_refine_evaluations, "refine");
  result.values = refined.values;
  result.rmse_search = refined.rmse;
  result.refine_stop = refined.stop;
  result.refine_evaluations = refined.evaluations;
  result.seconds["refine"] = seconds_since(stage_start);

  // 3. Uncertainty along 1-D scans through the optimum.
  stage_start = Clock::now();
  report(0.6, "scan");
  const double threshold = result.rmse_search * (1.0 + settings.uncertainty_fraction);
  for (std::size_t i = 0; i < n; ++i) {
    ParameterUncertainty u;
    u.name = parameters[i].name;
    u.value = result.values[i];
    u.scan_low = search.scan(result.values, i, parameters[i].min_value, threshold, all);
    u.scan_high = search.scan(result.values, i, parameters[i].max_value, threshold, all);
    result.uncertainty.push_back(u);
  }
  result.seconds["scan"] = seconds_since(stage_start);

  // 4. Per capture and cross-validation, from the grid's best point under each mask.
  const auto fold_fraction = [&](std::size_t k, double base) {
    return base + 0.1 * static_cast<double>(k + 1) / static_cast<double>(capture_count);
  };
  if (settings.per_capture) {
    stage_start = Clock::now();
    for (std::size_t k = 0; k < capture_count; ++k) {
      std::vector<bool> mask(capture_count, false);
      mask[k] = true;
      const auto [start, start_rmse] = search.best_of(grid, mask);
      const Refined r =
          search.refine(start, mask, settings.max_fold_refine_evaluations, "per_capture");
      result.captures[k].own_values = r.values;
      result.captures[k].own_rmse = r.rmse;
      report(fold_fraction(k, 0.65), "per_capture");
    }
    result.seconds["per_capture"] = seconds_since(stage_start);
  }
  if (settings.cross_validate && capture_count > 1) {
    stage_start = Clock::now();
    double sum = 0;
    std::size_t answered = 0;
    for (std::size_t k = 0; k < capture_count; ++k) {
      std::vector<bool> mask(capture_count, true);
      mask[k] = false;
      const auto [start, start_rmse] = search.best_of(grid, mask);
      const Refined r =
          search.refine(start, mask, settings.max_fold_refine_evaluations, "cross_validate");
      const double held_out = objective.capture_rmse(r.values, "cross_validate")[k];
      result.captures[k].fold_values = r.values;
      result.captures[k].held_out_rmse = held_out;
      if (!std::isnan(held_out)) {
        sum += held_out * held_out;
        ++answered;
      }
      report(fold_fraction(k, 0.75), "cross_validate");
    }
    if (answered > 0) result.cross_validated_rmse = std::sqrt(sum / static_cast<double>(answered));
    result.seconds["cross_validate"] = seconds_since(stage_start);
  }

  // The range over every point evaluated (the scans and folds included).
  for (std::size_t i = 0; i < n; ++i) {
    ParameterUncertainty& u = result.uncertainty[i];
    u.sampled_low = u.sampled_high = u.value;
    for (const FitSample& s : objective.history())
      if (s.rmse <= threshold) {
        u.sampled_low = std::min(u.sampled_low, s.values[i]);
        u.sampled_high = std::max(u.sampled_high, s.values[i]);
      }
  }

  // Confirmation at the standard setting.
  stage_start = Clock::now();
  report(0.9, "confirm");
  const EvaluationResult after =
      result.search_setting_differs
          ? evaluate_model(factory, with_values(settings.config, parameters, result.values),
                           captures, options)
          : objective.evaluate(result.values);
  result.rmse_after = after.rmse;
  for (std::size_t k = 0; k < capture_count; ++k)
    result.captures[k].rmse_after = after.captures[k].answered() ? after.captures[k].rmse : kNaN;
  result.seconds["confirm"] = seconds_since(stage_start);
  result.history = objective.history();
  result.seconds["total"] = seconds_since(start_all);
  report(1.0, "done");
  return result;
}

}  // namespace clearsky
