// An atmosphere fit to a broadband irradiance dataset (broadband_fit.h).
#include "api/fits/broadband_fit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "api/evaluation/broadband_evaluation.h"
#include "api/irradiance/broadband_irradiance.h"
#include "models/core/invalid_input.h"
#include "models/core/precompute_context.h"
#include "models/solar/solar_position.h"

namespace clearsky::api {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The samples with the sun up, at most `limit`, evenly spread by index.
std::vector<storage::IrradianceSample> search_samples(
    const std::vector<storage::IrradianceSample>& samples, std::size_t limit) {
  std::vector<storage::IrradianceSample> day;
  for (const auto& s : samples) {
    SolarPositionInput input;
    input.unix_time_utc_s = s.time_utc_s;
    input.latitude_deg = s.latitude_deg;
    input.longitude_deg = s.longitude_deg;
    input.elevation_m = s.elevation_m;
    input.refraction = false;
    if (solar_position(input).zenith_deg < 90.0) day.push_back(s);
  }
  if (day.size() <= limit) return day;
  std::vector<storage::IrradianceSample> spread;
  for (std::size_t k = 0; k < limit; ++k) spread.push_back(day[k * day.size() / limit]);
  return spread;
}

class BroadbandObjective {
 public:
  BroadbandObjective(const ModelFactory& factory, const FitSettings& settings,
                     std::map<std::string, double> options)
      : factory_(factory), settings_(settings), options_(std::move(options)) {}

  double rmse(std::span<const double> values, const std::vector<storage::IrradianceSample>& samples,
              bool search_setting) const {
    if (settings_.cancel != nullptr && settings_.cancel->load()) throw PrecomputeCancelled();
    ModelConfig config = with_values(settings_.config, settings_.parameters, values);
    if (search_setting)
      for (const auto& [name, value] : options_) config.options[name] = value;
    const auto model = factory_.create(config, {});
    const auto results =
        compare_broadband_irradiance(samples, modelled_broadband_irradiance(*model, samples));
    return pooled_rmse_w_m2(results).value_or(std::numeric_limits<double>::quiet_NaN());
  }

 private:
  const ModelFactory& factory_;
  const FitSettings& settings_;
  std::map<std::string, double> options_;
};

// NaN (unanswered) ranks last.
bool better(double a, double b) { return std::isnan(b) || (!std::isnan(a) && a < b); }

}  // namespace

FitResult fit_broadband(const ModelFactory& factory,
                        const std::vector<storage::IrradianceSample>& samples,
                        const FitSettings& settings) {
  const ModelDescriptor& descriptor = *factory.descriptor;
  if (const auto unavailable = broadband_unavailable_reason(descriptor))
    throw InvalidInput("model", *unavailable);
  const auto total_start = Clock::now();
  const std::vector<storage::IrradianceSample> searched =
      search_samples(samples, kMaxBroadbandSearchSamples);
  if (searched.empty())
    throw std::invalid_argument("no irradiance sample with the sun above the horizon");
  const BroadbandObjective objective(factory, settings, settings.search_options);
  const auto& parameters = settings.parameters;

  FitResult result;
  result.model_id = descriptor.id;
  result.model_version = descriptor.version;
  result.parameters = parameters;
  result.search_options = settings.search_options;
  result.search_setting_differs = !settings.search_options.empty();
  result.refine_algorithm = "golden-section";
  for (const FreeParameter& p : parameters)
    result.initial_values.push_back(value_in(descriptor, settings.config, p));

  const auto report = [&](double fraction, std::string_view stage) {
    if (settings.progress) settings.progress(fraction, stage);
  };
  const auto evaluate = [&](const std::vector<double>& values, const char* stage) {
    const double rmse = objective.rmse(values, searched, true);
    result.history.push_back({stage, values, rmse});
    return rmse;
  };

  // 1. Grid.
  auto start = Clock::now();
  const std::vector<std::vector<double>> grid = grid_points(parameters);
  result.grid_rmse = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const double rmse = evaluate(grid[i], "grid");
    if (better(rmse, result.grid_rmse)) {
      result.grid_rmse = rmse;
      result.grid_values = grid[i];
    }
    report(0.5 * static_cast<double>(i + 1) / static_cast<double>(grid.size()), "grid");
  }
  result.grid_evaluations = grid.size();
  if (std::isnan(result.grid_rmse))
    throw std::invalid_argument("the model answers no sample at any grid point");
  result.seconds["grid"] = seconds_since(start);

  // 2. Golden-section refinement along each parameter in turn.
  start = Clock::now();
  std::vector<double> best = result.grid_values;
  double best_rmse = result.grid_rmse;
  const double inverse_phi = (std::sqrt(5.0) - 1.0) / 2.0;
  const int sweeps = parameters.size() > 1 ? 2 : 1;
  int evaluations = 0;
  result.refine_stop = "XTOL_REACHED";
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (std::size_t k = 0; k < parameters.size(); ++k) {
      const FreeParameter& p = parameters[k];
      const double width = p.max_value - p.min_value;
      const double step = p.grid_points > 1 ? width / (p.grid_points - 1) : width / 2;
      double a = std::max(p.min_value, best[k] - step);
      double b = std::min(p.max_value, best[k] + step);
      const auto at = [&](double x) {
        std::vector<double> values = best;
        values[k] = x;
        ++evaluations;
        const double rmse = evaluate(values, "refine");
        if (better(rmse, best_rmse)) {
          best_rmse = rmse;
          best = values;
        }
        return rmse;
      };
      double c = b - inverse_phi * (b - a), d = a + inverse_phi * (b - a);
      double fc = at(c), fd = at(d);
      while (b - a > settings.relative_tolerance * width) {
        if (evaluations >= settings.max_refine_evaluations) {
          result.refine_stop = "MAXEVAL_REACHED";
          break;
        }
        if (better(fc, fd)) {
          b = d;
          d = c;
          fd = fc;
          c = b - inverse_phi * (b - a);
          fc = at(c);
        } else {
          a = c;
          c = d;
          fc = fd;
          d = a + inverse_phi * (b - a);
          fd = at(d);
        }
        report(0.5 + 0.4 * std::min(1.0, evaluations / 40.0), "refine");
      }
    }
  result.refine_evaluations = static_cast<std::size_t>(evaluations);
  result.values = best;
  result.rmse_search = best_rmse;
  result.seconds["refine"] = seconds_since(start);

  // 3. Uncertainty from every point evaluated.
  for (std::size_t k = 0; k < parameters.size(); ++k) {
    ParameterUncertainty u;
    u.name = parameters[k].name;
    u.value = best[k];
    u.sampled_low = u.sampled_high = best[k];
    for (const FitSample& s : result.history)
      if (s.rmse <= best_rmse * (1.0 + settings.uncertainty_fraction)) {
        u.sampled_low = std::min(u.sampled_low, s.values[k]);
        u.sampled_high = std::max(u.sampled_high, s.values[k]);
      }
    u.scan_low = u.sampled_low;
    u.scan_high = u.sampled_high;
    result.uncertainty.push_back(u);
  }

  // 4. Confirmation at config's own setting on every sample.
  start = Clock::now();
  report(0.9, "confirm");
  std::vector<double> initial = result.initial_values;
  for (std::size_t k = 0; k < initial.size(); ++k)
    if (std::isnan(initial[k])) initial[k] = best[k];
  result.rmse_before = objective.rmse(initial, samples, false);
  result.rmse_after = objective.rmse(best, samples, false);
  result.seconds["confirm"] = seconds_since(start);
  result.seconds["total"] = seconds_since(total_start);
  report(1.0, "confirm");
  return result;
}

}  // namespace clearsky::api
