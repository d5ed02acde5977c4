// The objective of a fit (docs/fits.md "Objective"): the evaluation's RMSE (models/evaluation/
// evaluate_model.h, the same code `clearsky evaluate` runs: per-capture RMSE over 81 directions
// x 31 wavelengths of the prepared captures, total = sqrt of the mean of squared per-capture
// RMSE) of the model built with the free parameters at given values. Each point costs one model
// build (for table models, new tables) and one evaluation of every capture; the per-capture
// RMSEs of every point are kept, so that objectives over subsets of the captures (one capture,
// all but one) reuse the points already evaluated at no cost. Every evaluation is recorded in
// the history with the stage that asked for it.
// Not thread-safe: one fit uses it from one thread (the evaluation itself runs the captures in
// parallel, EvaluationOptions::capture_threads).
#pragma once

#include <chrono>
#include <cstddef>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "models/core/sky_model.h"
#include "models/evaluation/evaluate_model.h"
#include "models/fitting/fit_space.h"

namespace clearsky {

// One evaluated point: the free parameters' values, the RMSE over all the fit's captures
// (NaN when no capture was answered) and the stage ("grid", "refine", "scan", ...).
struct FitSample {
  std::string stage;
  std::vector<double> values;
  double rmse = 0;
};

class FitObjective {
 public:
  // captures: prepared (capture_preparation.h). config: the fixed parameters and options.
  FitObjective(const ModelFactory& factory, ModelConfig config,
               std::vector<FreeParameter> parameters, std::span<const MeasuredCapture> captures,
               EvaluationOptions options);

  // RMSE (mW/(m2.sr.nm)) per capture at values, NaN for an unanswered capture; evaluated once
  // per distinct point, recorded in the history under stage.
  const std::vector<double>& capture_rmse(std::span<const double> values, const std::string& stage);
  // sqrt(mean of squared RMSE) over the captures whose mask is true and that the model
  // answered; NaN when none (evaluate_model.h's total over a subset).
  static double combined_rmse(std::span<const double> capture_rmse, const std::vector<bool>& mask);
  // The full evaluation at values (with per-sample results), not cached.
  EvaluationResult evaluate(std::span<const double> values) const;

  const std::vector<FreeParameter>& parameters() const { return parameters_; }
  std::size_t capture_count() const { return captures_.size(); }
  const std::vector<FitSample>& history() const { return history_; }
  std::size_t evaluations() const { return history_.size(); }
  double seconds() const { return seconds_; }  // wall time spent in builds and evaluations

 private:
  const ModelFactory* factory_;
  ModelConfig config_;
  std::vector<FreeParameter> parameters_;
  std::span<const MeasuredCapture> captures_;
  EvaluationOptions options_;
  std::map<std::vector<double>, std::vector<double>> cache_;
  std::vector<FitSample> history_;
  double seconds_ = 0;
};

}  // namespace clearsky
