// Atmosphere fits as JSON (fit_json.h).
#include "api/encode/fit_json.h"

#include <cmath>

namespace clearsky::api {

namespace {

nlohmann::json number_or_null(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

nlohmann::json named_values(std::span<const FreeParameter> parameters,
                            std::span<const double> values) {
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t i = 0; i < parameters.size() && i < values.size(); ++i)
    out[parameters[i].name] = number_or_null(values[i]);
  return out;
}

nlohmann::json parse_stored(const std::string& text) {
  return text.empty() ? nlohmann::json(nullptr) : nlohmann::json::parse(text);
}

}  // namespace

nlohmann::json free_parameters_json(std::span<const FreeParameter> parameters) {
  nlohmann::json out = nlohmann::json::array();
  for (const FreeParameter& p : parameters)
    out.push_back({{"name", p.name},
                   {"min", p.min_value},
                   {"max", p.max_value},
                   {"grid_points", p.grid_points}});
  return out;
}

storage::FitOutcome fit_outcome(const FitResult& r) {
  storage::FitOutcome o;
  const std::span<const FreeParameter> p = r.parameters;
  o.result = nlohmann::json{{"values", named_values(p, r.values)},
                            {"initial_values", named_values(p, r.initial_values)},
                            {"grid",
                             {{"values", named_values(p, r.grid_values)},
                              {"rmse", number_or_null(r.grid_rmse)},
                              {"evaluations", r.grid_evaluations}}},
                            {"refine",
                             {{"algorithm", r.refine_algorithm},
                              {"stop", r.refine_stop},
                              {"evaluations", r.refine_evaluations}}},
                            {"search_setting_differs", r.search_setting_differs},
                            {"evaluations", r.history.size()}}
                 .dump();
  o.rmse_before = r.rmse_before;
  o.rmse_search = r.rmse_search;
  o.rmse_after = r.rmse_after;
  o.cross_validated_rmse = r.cross_validated_rmse;
  nlohmann::json captures = nlohmann::json::array();
  for (const CaptureFit& c : r.captures) {
    nlohmann::json j = {{"label", c.label},
                        {"rmse_before", number_or_null(c.rmse_before)},
                        {"rmse_after", number_or_null(c.rmse_after)}};
    if (!c.own_values.empty()) {
      j["own_values"] = named_values(p, c.own_values);
      j["own_rmse"] = number_or_null(c.own_rmse);
    }
    if (!c.fold_values.empty()) {
      j["fold_values"] = named_values(p, c.fold_values);
      j["held_out_rmse"] = number_or_null(c.held_out_rmse);
    }
    captures.push_back(std::move(j));
  }
  o.per_capture = captures.dump();
  nlohmann::json uncertainty = nlohmann::json::array();
  for (const ParameterUncertainty& u : r.uncertainty)
    uncertainty.push_back({{"name", u.name},
                           {"value", u.value},
                           {"scan", {u.scan_low, u.scan_high}},
                           {"sampled", {u.sampled_low, u.sampled_high}}});
  o.uncertainty = uncertainty.dump();
  nlohmann::json history = nlohmann::json::array();
  for (const FitSample& s : r.history)
    history.push_back({{"stage", s.stage}, {"values", s.values}, {"rmse", number_or_null(s.rmse)}});
  o.history = history.dump();
  nlohmann::json seconds = nlohmann::json::object();
  for (const auto& [stage, value] : r.seconds) seconds[stage] = value;
  o.timings = seconds.dump();
  return o;
}

nlohmann::json fit_to_json(const storage::FitRecord& record, bool with_history) {
  nlohmann::json out = {
      {"id", record.id},
      {"dataset", record.dataset},
      {"model", record.fit.model_id},
      {"model_version", record.fit.model_version},
      {"status", record.fit.status},
      {"progress", record.progress},
      {"stage", record.stage ? nlohmann::json(*record.stage) : nullptr},
      {"free_parameters", parse_stored(record.fit.free_parameters)},
      {"parameters", parse_stored(record.fit.fixed_parameters)},
      {"search_options", parse_stored(record.fit.search_options)},
      {"captures", parse_stored(record.fit.captures)},
      {"settings", parse_stored(record.fit.settings)},
      {"software_version", record.fit.software_version},
      {"created_utc", record.created_utc},
      {"finished_utc", record.finished_utc ? nlohmann::json(*record.finished_utc) : nullptr}};
  if (record.error) out["error"] = *record.error;
  if (record.outcome) {
    const storage::FitOutcome& o = *record.outcome;
    nlohmann::json result = parse_stored(o.result);
    out["values"] = result["values"];
    out["rmse_before"] = number_or_null(o.rmse_before);
    out["rmse_search"] = number_or_null(o.rmse_search);
    out["rmse_after"] = number_or_null(o.rmse_after);
    out["cross_validated_rmse"] =
        o.cross_validated_rmse ? number_or_null(*o.cross_validated_rmse) : nullptr;
    out["search"] = std::move(result);
    out["uncertainty"] = parse_stored(o.uncertainty);
    out["captures_fitted"] = parse_stored(o.per_capture);
    out["seconds"] = parse_stored(o.timings);
    if (with_history) out["history"] = parse_stored(o.history);
  }
  return out;
}

}  // namespace clearsky::api
