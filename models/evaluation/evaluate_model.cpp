// RMSE of a model against measured skies (evaluate_model.h).
#include "models/evaluation/evaluate_model.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "models/core/fit_domain.h"
#include "models/core/invalid_input.h"
#include "models/core/numeric.h"
#include "models/core/parallel.h"

namespace clearsky {

std::string_view to_string(OutOfDomain handling) {
  return handling == OutOfDomain::clamp ? "clamp" : "exclude";
}

std::optional<OutOfDomain> out_of_domain_from_string(std::string_view text) {
  if (text == "exclude") return OutOfDomain::exclude;
  if (text == "clamp") return OutOfDomain::clamp;
  return std::nullopt;
}

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The sun azimuth given to the model: the estimated one when asked and the capture has one
// (capture_preparation.h estimates it for the 81-direction layout only), else the computed one.
double sun_azimuth_of(const MeasuredCapture& capture, const EvaluationOptions& options) {
  return options.use_estimated_sun_azimuth && std::isfinite(capture.sun_azimuth_estimated_deg)
             ? capture.sun_azimuth_estimated_deg
             : capture.sun_azimuth_computed_deg;
}

void check_prepared(const MeasuredCapture& capture, const EvaluationOptions& options) {
  const double azimuth = sun_azimuth_of(capture, options);
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

void add_sample(std::vector<OutOfDomainSamples>& lists, SampleStatus reason, int index) {
  auto it = std::find_if(lists.begin(), lists.end(),
                         [&](const OutOfDomainSamples& l) { return l.reason == reason; });
  if (it == lists.end()) {
    it = std::upper_bound(lists.begin(), lists.end(), reason,
                          [](SampleStatus r, const OutOfDomainSamples& l) { return r < l.reason; });
    it = lists.insert(it, OutOfDomainSamples{reason, {}});
  }
  it->indices.push_back(index);
}

void sort_indices(std::vector<OutOfDomainSamples>& lists) {
  for (OutOfDomainSamples& l : lists) std::sort(l.indices.begin(), l.indices.end());
}

// Every sample of the capture left out for one reason (the capture is unanswered).
void exclude_all(CaptureEvaluation& result, const MeasuredCapture& capture, SampleStatus reason) {
  result.samples.clear();
  result.sample_errors.clear();
  result.clamped.clear();
  result.excluded.clear();
  for (const MeasuredSample& s : capture.samples) add_sample(result.excluded, reason, s.index);
  sort_indices(result.excluded);
  result.rmse = 0;
  result.values_compared = 0;
}

CaptureEvaluation evaluate_capture(const SkyModel& model, const SkyModel* fit_clamped,
                                   const MeasuredCapture& capture,
                                   const std::vector<std::size_t>& compared,
                                   const EvaluationOptions& options) {
  const bool clamp = options.out_of_domain == OutOfDomain::clamp;
  const ModelCapabilities& caps = model.descriptor().capabilities;
  CaptureEvaluation result;
  result.label = capture.label;
  result.time_iso = local_time_iso8601(capture);
  result.unix_time_utc_s = capture.unix_time_utc_s;
  result.sun_zenith_deg = capture.sun_zenith_computed_deg;
  result.sun_azimuth_deg = sun_azimuth_of(capture, options);
  result.samples_measured = capture.samples.size();
  if (compared.empty()) {
    exclude_all(result, capture, SampleStatus::wavelength_out_of_range);
    return result;
  }
  SunPosition sun{result.sun_zenith_deg * kDegree, result.sun_azimuth_deg * kDegree};
  SampleStatus sun_status = model.check_sun(sun);
  if (sun_status == SampleStatus::sun_below_horizon_unsupported && clamp) {
    // The nearest sun the model answers: at its largest zenith angle.
    result.sun_zenith_deg = caps.max_sun_zenith_deg;
    sun.zenith_rad = result.sun_zenith_deg * kDegree;
    for (const MeasuredSample& s : capture.samples)
      add_sample(result.clamped, SampleStatus::sun_below_horizon_unsupported, s.index);
    sun_status = model.check_sun(sun);
  }
  if (sun_status != SampleStatus::ok) {
    exclude_all(result, capture, sun_status);
    return result;
  }
  std::shared_ptr<const SunState> sun_state, clamped_sun_state;
  try {
    sun_state = model.prepare_sun(sun, options.context);
  } catch (const InvalidInput&) {
    exclude_all(result, capture, SampleStatus::invalid_input);
    return result;
  }

  Viewpoint viewpoint{options.viewer_altitude_m};
  if (clamp && std::isfinite(viewpoint.altitude_m) &&
      (viewpoint.altitude_m < caps.min_altitude_m || viewpoint.altitude_m > caps.max_altitude_m)) {
    viewpoint.altitude_m =
        std::clamp(viewpoint.altitude_m, caps.min_altitude_m, caps.max_altitude_m);
    for (const MeasuredSample& s : capture.samples)
      add_sample(result.clamped, SampleStatus::viewpoint_unsupported, s.index);
  }
  std::vector<ViewDirection> views;
  views.reserve(capture.samples.size());
  for (const MeasuredSample& s : capture.samples) {
    ViewDirection view = s.view;
    if (clamp && !caps.view_below_horizon && view.zenith_rad > 0.5 * kPi) {
      view.zenith_rad = 0.5 * kPi;  // the horizon, the nearest view the model answers
      add_sample(result.clamped, SampleStatus::view_below_horizon_unsupported, s.index);
    }
    views.push_back(view);
  }
  SpectralBatch radiance;
  model.sky_radiance(*sun_state, viewpoint, views, radiance);

  // Outside the fit domain: under clamp, the same model with clamp_negative_fit answers them.
  if (clamp && fit_clamped != nullptr) {
    std::vector<std::size_t> outside;
    for (std::size_t s = 0; s < views.size(); ++s)
      if (radiance.status[s] == SampleStatus::outside_fit_domain) outside.push_back(s);
    if (!outside.empty()) {
      std::vector<ViewDirection> again;
      for (std::size_t s : outside) again.push_back(views[s]);
      SpectralBatch clamped;
      fit_clamped->sky_radiance(*fit_clamped->prepare_sun(sun, options.context), viewpoint, again,
                                clamped);
      for (std::size_t k = 0; k < outside.size(); ++k) {
        const std::size_t s = outside[k];
        radiance.status[s] = clamped.status[k];
        const auto from = clamped.spectrum(k);
        std::copy(from.begin(), from.end(), radiance.spectrum(s).begin());
        if (clamped.status[k] == SampleStatus::ok)
          add_sample(result.clamped, SampleStatus::outside_fit_domain, capture.samples[s].index);
      }
    }
  }

  const WavelengthGrid& grid = model.wavelengths();
  const std::size_t n_samples = capture.samples.size();
  const double n_compared = static_cast<double>(compared.size());
  result.samples.reserve(n_samples);
  result.sample_errors.reserve(n_samples * compared.size());
  double sum_squares = 0;
  for (std::size_t s = 0; s < n_samples; ++s) {
    if (radiance.status[s] == SampleStatus::numerical_failure)
      throw std::runtime_error(model.descriptor().id + " failed on capture " + capture.label +
                               " sample " + std::to_string(capture.samples[s].index) + ": " +
                               std::string(describe(radiance.status[s])));
    if (radiance.status[s] != SampleStatus::ok) {
      add_sample(result.excluded, radiance.status[s], capture.samples[s].index);
      continue;
    }
    // A measured spectrum that does not reach every compared wavelength (the open format's
    // spectra may cover any range) is left out, as a wavelength the model cannot answer is.
    const TabulatedSpectrum& measured_spectrum = capture.samples[s].radiance;
    if (measured_spectrum.min_nm() > grid[compared.front()] ||
        measured_spectrum.max_nm() < grid[compared.back()]) {
      add_sample(result.excluded, SampleStatus::wavelength_out_of_range, capture.samples[s].index);
      continue;
    }
    const auto values = radiance.spectrum(s);
    const std::size_t row = result.sample_errors.size();
    result.sample_errors.resize(row + compared.size());
    double* errors = result.sample_errors.data() + row;
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
    SampleEvaluation& sample = result.samples.emplace_back();
    sample.index = capture.samples[s].index;
    sample.view_zenith_deg = radians_to_degrees(capture.samples[s].view.zenith_rad);
    sample.view_azimuth_deg = radians_to_degrees(capture.samples[s].view.azimuth_rad);
    sample.rmse = 1000.0 * std::sqrt(sample_squares / n_compared);
    sample.bias = 1000.0 * sample_sum / n_compared;
  }
  sort_indices(result.excluded);
  sort_indices(result.clamped);
  // A sample clamped for a reason but then excluded for another is listed as excluded only.
  for (OutOfDomainSamples& c : result.clamped) {
    std::erase_if(c.indices, [&](int index) {
      return std::none_of(result.samples.begin(), result.samples.end(),
                          [&](const SampleEvaluation& e) { return e.index == index; });
    });
  }
  std::erase_if(result.clamped, [](const OutOfDomainSamples& c) { return c.indices.empty(); });
  result.values_compared = result.samples.size() * compared.size();
  if (!result.answered()) {
    result.rmse = 0;
    return result;
  }
  // W/(m2.sr.nm) -> mW/(m2.sr.nm).
  result.rmse = 1000.0 * std::sqrt(sum_squares / static_cast<double>(result.values_compared));
  return result;
}

}  // namespace

EvaluationResult evaluate_sky_model(const SkyModel& model,
                                    std::span<const MeasuredCapture> captures,
                                    const EvaluationOptions& options, const SkyModel* fit_clamped) {
  if (captures.empty()) throw std::invalid_argument("evaluation: no captures");
  for (const MeasuredCapture& capture : captures) check_prepared(capture, options);
  const WavelengthGrid& grid = model.wavelengths();
  std::vector<std::size_t> compared;
  EvaluationResult result;
  // The wavelengths some measured spectrum reaches: the compared range is at most theirs (all
  // of it for Kider's 350..2500 nm spectra), the samples that reach less are left out.
  double measured_min_nm = std::numeric_limits<double>::infinity();
  double measured_max_nm = -std::numeric_limits<double>::infinity();
  for (const MeasuredCapture& capture : captures) {
    for (const MeasuredSample& s : capture.samples) {
      measured_min_nm = std::min(measured_min_nm, s.radiance.min_nm());
      measured_max_nm = std::max(measured_max_nm, s.radiance.max_nm());
    }
  }
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (grid[i] >= options.min_wavelength_nm - 1e-9 &&
        grid[i] <= options.max_wavelength_nm + 1e-9 && model.answers_wavelength(i) &&
        grid[i] >= measured_min_nm && grid[i] <= measured_max_nm) {
      compared.push_back(i);
      result.wavelengths_nm.push_back(grid[i]);
    }
  }
  result.model_id = model.descriptor().id;
  result.model_version = model.descriptor().version;

  const auto start = std::chrono::steady_clock::now();
  result.captures.resize(captures.size());
  parallel_for(
      captures.size(),
      [&](std::size_t c) {
        result.captures[c] = evaluate_capture(model, fit_clamped, captures[c], compared, options);
      },
      options.capture_threads);
  double sum_squares = 0;
  std::size_t answered = 0;
  for (const CaptureEvaluation& c : result.captures) {
    result.samples_compared += c.samples.size();
    for (const OutOfDomainSamples& e : c.excluded) result.samples_excluded += e.indices.size();
    std::vector<int> clamped;
    for (const OutOfDomainSamples& e : c.clamped)
      clamped.insert(clamped.end(), e.indices.begin(), e.indices.end());
    std::sort(clamped.begin(), clamped.end());
    result.samples_clamped +=
        static_cast<std::size_t>(std::unique(clamped.begin(), clamped.end()) - clamped.begin());
    if (!c.answered()) {
      ++result.captures_unanswered;
      continue;
    }
    sum_squares += c.rmse * c.rmse;
    ++answered;
  }
  result.rmse = answered == 0 ? std::numeric_limits<double>::quiet_NaN()
                              : std::sqrt(sum_squares / static_cast<double>(answered));
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
  std::shared_ptr<const SkyModel> fit_clamped;
  if (options.out_of_domain == OutOfDomain::clamp &&
      factory.descriptor->find_parameter(kClampNegativeFitOption) != nullptr &&
      option_or_default(*factory.descriptor, config, kClampNegativeFitOption) == 0.0) {
    ModelConfig clamped = config;
    clamped.options[kClampNegativeFitOption] = 1.0;
    fit_clamped = factory.create(clamped, options.context);
  }
  const double precompute_seconds = seconds_since(start);
  EvaluationResult result = evaluate_sky_model(*model, captures, options, fit_clamped.get());
  result.precompute_seconds = precompute_seconds;
  return result;
}

}  // namespace clearsky
