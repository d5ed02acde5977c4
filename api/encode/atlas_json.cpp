// Atlas report encoding (atlas_json.h).
#include "api/encode/atlas_json.h"

#include <cmath>

namespace clearsky::api {

namespace {

nlohmann::json number_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

nlohmann::json errors_to_json(const atlas::ErrorSummary& e) {
  return {{"median", number_or_null(e.median)},
          {"p95", number_or_null(e.p95)},
          {"max", number_or_null(e.max)},
          {"samples", e.count}};
}

nlohmann::json measurement_to_json(const atlas::SettingMeasurement& m) {
  nlohmann::json options = nlohmann::json::object();
  for (const auto& [name, value] : m.setting.options) options[name] = number_or_null(value);
  return {{"name", m.setting.name},
          {"role", m.role},
          {"options", options},
          {"grid", atlas::to_string(m.setting.grid)},
          {"wavelengths", m.wavelengths},
          {"build_wall_s", number_or_null(m.build_wall_s)},
          {"build_cpu_s", number_or_null(m.build_cpu_s)},
          {"table_bytes", m.table_bytes},
          {"estimated_table_bytes", m.estimated_table_bytes},
          {"sun_state_wall_s", number_or_null(m.sun_state_wall_s)},
          {"radiance_s", number_or_null(m.radiance_s)},
          {"batch_81_s", number_or_null(m.batch_81_s)},
          {"sky_irradiance_s", number_or_null(m.sky_irradiance_s)},
          {"first_sky_s", number_or_null(m.first_sky_s())},
          {"spectral_error", errors_to_json(m.spectral_error)},
          {"luminance_error", errors_to_json(m.luminance_error)},
          {"samples_refused", m.samples_refused},
          {"rmse", m.rmse ? number_or_null(*m.rmse) : nlohmann::json(nullptr)},
          {"rmse_wavelengths", m.rmse_wavelengths},
          {"evaluate_s", number_or_null(m.evaluate_s)}};
}

}  // namespace

nlohmann::json atlas_report_to_json(const atlas::ModelAtlasReport& r) {
  nlohmann::json settings = nlohmann::json::array();
  for (const atlas::SettingMeasurement& m : r.settings) settings.push_back(measurement_to_json(m));
  return {{"model", r.model},
          {"version", r.version},
          {"geometry",
           {{"sun_zeniths_deg", r.sun_zeniths_deg},
            {"altitudes_m", r.altitudes_m},
            {"views", r.views}}},
          {"reference", measurement_to_json(r.reference)},
          {"reference_reason", r.reference_reason},
          {"reference_check",
           r.reference_check ? measurement_to_json(*r.reference_check) : nlohmann::json(nullptr)},
          {"settings", settings},
          {"pareto_build", r.pareto_build},
          {"pareto_query", r.pareto_query},
          {"draft", r.draft.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.draft)},
          {"seconds", number_or_null(r.seconds)}};
}

}  // namespace clearsky::api
