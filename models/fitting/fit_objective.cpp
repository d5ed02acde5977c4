// The objective of a fit (fit_objective.h).
#include "models/fitting/fit_objective.h"

#include <cmath>
#include <limits>

namespace clearsky {

FitObjective::FitObjective(const ModelFactory& factory, ModelConfig config,
                           std::vector<FreeParameter> parameters,
                           std::span<const MeasuredCapture> captures, EvaluationOptions options)
    : factory_(&factory),
      config_(std::move(config)),
      parameters_(std::move(parameters)),
      captures_(captures),
      options_(std::move(options)) {}

EvaluationResult FitObjective::evaluate(std::span<const double> values) const {
  return evaluate_model(*factory_, with_values(config_, parameters_, values), captures_, options_);
}

const std::vector<double>& FitObjective::capture_rmse(std::span<const double> values,
                                                      const std::string& stage) {
  std::vector<double> key(values.begin(), values.end());
  auto it = cache_.find(key);
  if (it == cache_.end()) {
    const auto start = std::chrono::steady_clock::now();
    const EvaluationResult result = evaluate(values);
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::vector<double> per_capture;
    for (const CaptureEvaluation& c : result.captures)
      per_capture.push_back(c.answered() ? c.rmse : std::numeric_limits<double>::quiet_NaN());
    it = cache_.emplace(key, std::move(per_capture)).first;
    history_.push_back({stage, key, result.rmse});
  }
  return it->second;
}

double FitObjective::combined_rmse(std::span<const double> capture_rmse,
                                   const std::vector<bool>& mask) {
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < capture_rmse.size(); ++i)
    if (mask[i] && !std::isnan(capture_rmse[i])) {
      sum += capture_rmse[i] * capture_rmse[i];
      ++n;
    }
  return n == 0 ? std::numeric_limits<double>::quiet_NaN()
                : std::sqrt(sum / static_cast<double>(n));
}

}  // namespace clearsky
