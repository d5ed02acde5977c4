// RMSE of a model against measured skies (evaluate_model.h).
#include "models/evaluation/evaluate_model.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "models/core/numeric.h"
#include "models/core/parallel.h"

namespace clearsky {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void check_prepared(const MeasuredCapture& capture, const EvaluationOptions& options) {
  const double azimuth = options.use_estimated_sun_azimuth ? capture.sun_azimuth_estimated_deg
                                                           : capture.sun_azimuth_computed_deg;
  if (!std::isfinite(capture.sun_zenith_computed_deg) || !std::isfinite(azimuth))
    throw std::invalid_argument("capture " + capture.label +
                                " has no sun position (prepare it with prepare_capture first)");
  for (const MeasuredSample& s : capture.samples) {
    if ((s.quality_flags & kSampleKnownDefective) != 0 && (s.quality_flags & kSampleRepaired) == 0)
      throw std::invalid_argument("capture " + capture.label + ": sample " +
                                  std::to_string(s.index) +
                                  " is known to be defective and not repaired");
  }
  if (capture.samples.empty())
    throw std::invalid_argument("capture " + capture.label + " has no samples");
}

CaptureEvaluation evaluate_capture(const SkyModel& model, const MeasuredCapture& capture,
                                   const std::vector<std::size_t>& compared,
                                   const EvaluationOptions& options) {
  CaptureEvaluation result;
  result.label = capture.label;
  result.time_iso = local_time_iso8601(capture);
  result.unix_time_utc_s = capture.unix_time_utc_s;
  result.sun_zenith_deg = capture.sun_zenith_computed_deg;
  result.sun_azimuth_deg = options.use_estimated_sun_azimuth ? capture.sun_azimuth_estimated_deg
                                                             : capture.sun_azimuth_computed_deg;
  const SunPosition sun{result.sun_zenith_deg * kDegree, result.sun_azimuth_deg * kDegree};
  if (const SampleStatus status = model.check_sun(sun); status != SampleStatus::ok)
    throw std::runtime_error(model.descriptor().id + " cannot answer capture " + capture.label +
                             ": " + std::string(describe(status)));
  const auto sun_state = model.prepare_sun(sun, options.context);

  std::vector<ViewDirection> views;
  views.reserve(capture.samples.size());
  for (const MeasuredSample& s : capture.samples) views.push_back(s.view);
  SpectralBatch radiance;
  model.sky_radiance(*sun_state, Viewpoint{options.viewer_altitude_m}, views, radiance);

  const WavelengthGrid& grid = model.wavelengths();
  const std::size_t n_samples = capture.samples.size();
  const double n_compared = static_cast<double>(compared.size());
  result.samples.resize(n_samples);
  result.sample_errors.resize(n_samples * compared.size());
  double sum_squares = 0;
  for (std::size_t s = 0; s < n_samples; ++s) {
    if (radiance.status[s] != SampleStatus::ok)
      throw std::runtime_error(model.descriptor().id + " cannot answer capture " + capture.label +
                               " sample " + std::to_string(capture.samples[s].index) + ": " +
                               std::string(describe(radiance.status[s])));
    const auto values = radiance.spectrum(s);
    double* errors = result.sample_errors.data() + s * compared.size();
    double sample_squares = 0;
    double sample_sum = 0;
    for (std::size_t k = 0; k < compared.size(); ++k) {
      const std::size_t i = compared[k];
      const double measured = capture.samples[s].radiance.at(grid[i], OutOfRange::error);
      const double difference = values[i] - measured;
      sample_squares += difference * difference;
      sample_sum += difference;
      errors[k] = 1000.0 * difference;  // W -> mW
    }
    sum_squares += sample_squares;
    SampleEvaluation& sample = result.samples[s];
    sample.index = capture.samples[s].index;
    sample.view_zenith_deg = radians_to_degrees(capture.samples[s].view.zenith_rad);
    sample.view_azimuth_deg = radians_to_degrees(capture.samples[s].view.azimuth_rad);
    sample.rmse = 1000.0 * std::sqrt(sample_squares / n_compared);
    sample.bias = 1000.0 * sample_sum / n_compared;
  }
  result.values_compared = n_samples * compared.size();
  // W/(m2.sr.nm) -> mW/(m2.sr.nm).
  result.rmse = 1000.0 * std::sqrt(sum_squares / static_cast<double>(result.values_compared));
  return result;
}

}  // namespace

EvaluationResult evaluate_sky_model(const SkyModel& model,
                                    std::span<const MeasuredCapture> captures,
                                    const EvaluationOptions& options) {
  if (captures.empty()) throw std::invalid_argument("evaluation: no captures");
  for (const MeasuredCapture& capture : captures) check_prepared(capture, options);
  const WavelengthGrid& grid = model.wavelengths();
  std::vector<std::size_t> compared;
  EvaluationResult result;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (grid[i] >= options.min_wavelength_nm - 1e-9 &&
        grid[i] <= options.max_wavelength_nm + 1e-9 && model.answers_wavelength(i)) {
      compared.push_back(i);
      result.wavelengths_nm.push_back(grid[i]);
    }
  }
  if (compared.empty())
    throw std::invalid_argument(
        "evaluation: the model answers no grid wavelength inside the compared range");
  result.model_id = model.descriptor().id;
  result.model_version = model.descriptor().version;

  const auto start = std::chrono::steady_clock::now();
  result.captures.resize(captures.size());
  parallel_for(
      captures.size(),
      [&](std::size_t c) {
        result.captures[c] = evaluate_capture(model, captures[c], compared, options);
      },
      options.capture_threads);
  double sum_squares = 0;
  for (const CaptureEvaluation& c : result.captures) sum_squares += c.rmse * c.rmse;
  result.rmse = std::sqrt(sum_squares / static_cast<double>(result.captures.size()));
  result.evaluate_seconds = seconds_since(start);
  return result;
}

EvaluationResult evaluate_model(const ModelFactory& factory, const ModelConfig& config,
                                std::span<const MeasuredCapture> captures,
                                const EvaluationOptions& options) {
  if (factory.create == nullptr || factory.descriptor == nullptr)
    throw std::invalid_argument("evaluation: incomplete model factory");
  const auto start = std::chrono::steady_clock::now();
  const std::shared_ptr<const SkyModel> model = factory.create(config, options.context);
  const double precompute_seconds = seconds_since(start);
  EvaluationResult result = evaluate_sky_model(*model, captures, options);
  result.precompute_seconds = precompute_seconds;
  return result;
}

}  // namespace clearsky
