// Evaluation results and datasets as JSON (evaluation_json.h).
#include "api/encode/evaluation_json.h"

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

nlohmann::ordered_json evaluation_to_json(const EvaluationReport& report) {
  nlohmann::ordered_json models = nlohmann::ordered_json::array();
  for (const ModelRun& run : report.models) {
    const EvaluationResult& r = run.result;
    nlohmann::ordered_json captures = nlohmann::ordered_json::array();
    for (const CaptureEvaluation& c : r.captures) {
      captures.push_back({{"time", c.time_iso},
                          {"sun_zenith", finite(c.sun_zenith_deg, "sun zenith")},
                          {"sun_azimuth", finite(c.sun_azimuth_deg, "sun azimuth")},
                          {"rmse", finite(c.rmse, "capture RMSE")}});
    }
    models.push_back({{"model", r.model_id},
                      {"rmse", finite(r.rmse, "RMSE")},
                      {"captures", std::move(captures)},
                      {"precompute_seconds", finite(r.precompute_seconds, "precompute time")},
                      {"evaluate_seconds", finite(r.evaluate_seconds, "evaluate time")}});
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
