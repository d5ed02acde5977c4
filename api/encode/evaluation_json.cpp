// Evaluation results and datasets as JSON (evaluation_json.h).
#include "api/encode/evaluation_json.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace clearsky::api {
namespace {

double finite(double value, const char* what) {
  if (!std::isfinite(value))
    throw std::runtime_error(std::string("evaluation result: non-finite ") + what);
  return value;
}

// Whole numbers as JSON integers ([360, 720] as the contract writes them).
nlohmann::ordered_json number(double value) {
  if (std::isfinite(value) && std::floor(value) == value && std::abs(value) < 1e15)
    return static_cast<std::int64_t>(value);
  return value;
}

}  // namespace

nlohmann::ordered_json float_to_json(float value) {
  if (!std::isfinite(value)) throw std::runtime_error("evaluation result: non-finite sample value");
  char text[32];
  const auto written = std::to_chars(text, text + sizeof text, value);
  double shortest = 0;
  std::from_chars(text, written.ptr, shortest);
  return shortest;
}

nlohmann::ordered_json sample_handling_to_json(const std::vector<storage::SampleHandling>& stored,
                                               std::string_view handling) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const storage::SampleHandling& h : stored) {
    if (h.handling != handling) continue;
    out.push_back({{"reason", h.reason}, {"count", h.indices.size()}, {"samples", h.indices}});
  }
  return out;
}

nlohmann::ordered_json samples_to_json(const storage::SampleErrorTable& samples,
                                       SampleDetail detail) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  if (detail == SampleDetail::none) return out;
  for (std::size_t s = 0; s < samples.samples.size(); ++s) {
    const storage::StoredSampleError& e = samples.samples[s];
    nlohmann::ordered_json sample = {{"index", e.index},
                                     {"view_zenith", float_to_json(e.view_zenith_deg)},
                                     {"view_azimuth", float_to_json(e.view_azimuth_deg)},
                                     {"rmse", finite(e.rmse, "sample RMSE")},
                                     {"bias", finite(e.bias, "sample bias")}};
    if (detail == SampleDetail::spectra) {
      nlohmann::ordered_json errors = nlohmann::ordered_json::array();
      for (float v : samples.errors_of(s)) errors.push_back(float_to_json(v));
      sample["errors"] = std::move(errors);
    }
    out.push_back(std::move(sample));
  }
  return out;
}

nlohmann::ordered_json evaluation_to_json(const EvaluationReport& report, SampleDetail samples) {
  nlohmann::ordered_json models = nlohmann::ordered_json::array();
  for (const ModelRun& run : report.models) {
    const EvaluationResult& r = run.result;
    nlohmann::ordered_json captures = nlohmann::ordered_json::array();
    for (const CaptureEvaluation& c : r.captures) {
      const auto handling = stored_sample_handling(c);
      nlohmann::ordered_json capture = {
          {"time", c.time_iso},
          {"sun_zenith", finite(c.sun_zenith_deg, "sun zenith")},
          {"sun_azimuth", finite(c.sun_azimuth_deg, "sun azimuth")},
          {"rmse", c.answered() ? nlohmann::ordered_json(finite(c.rmse, "capture RMSE"))
                                : nlohmann::ordered_json(nullptr)},
          {"samples_compared", c.samples.size()},
          {"excluded", sample_handling_to_json(handling, "excluded")},
          {"clamped", sample_handling_to_json(handling, "clamped")}};
      if (samples != SampleDetail::none)
        capture["samples"] =
            samples_to_json(stored_sample_errors(c, r.wavelengths_nm.size()), samples);
      captures.push_back(std::move(capture));
    }
    nlohmann::ordered_json model = {
        {"model", r.model_id},
        {"rmse", r.samples_compared == 0 ? nlohmann::ordered_json(nullptr)
                                         : nlohmann::ordered_json(finite(r.rmse, "RMSE"))},
        {"out_of_domain", to_string(report.out_of_domain)},
        {"samples_compared", r.samples_compared},
        {"samples_excluded", r.samples_excluded},
        {"samples_clamped", r.samples_clamped},
        {"captures_unanswered", r.captures_unanswered}};
    if (samples == SampleDetail::spectra) model["wavelengths_nm"] = r.wavelengths_nm;
    model["captures"] = std::move(captures);
    model["precompute_seconds"] = finite(r.precompute_seconds, "precompute time");
    model["evaluate_seconds"] = finite(r.evaluate_seconds, "evaluate time");
    models.push_back(std::move(model));
  }
  return {
      {"dataset", report.dataset},
      {"wavelength_range_nm", {number(report.min_wavelength_nm), number(report.max_wavelength_nm)}},
      {"models", std::move(models)}};
}

nlohmann::ordered_json datasets_to_json(const std::vector<storage::DatasetSummary>& datasets) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const auto& d : datasets)
    out.push_back({{"name", d.name}, {"captures", d.captures}, {"samples", d.samples}});
  return out;
}

}  // namespace clearsky::api
