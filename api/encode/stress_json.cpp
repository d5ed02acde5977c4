// Stress report encoding (stress_json.h).
#include "api/encode/stress_json.h"

#include <cmath>
#include <string>

#include "models/stress/documented_limits.h"
#include "models/stress/model_stress.h"

namespace clearsky::api {

namespace {

nlohmann::json number_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

nlohmann::json check_to_json(const stress::BoundCheck& c) {
  return {{"name", c.name},
          {"bound", c.bound},
          {"checked", c.checked},
          {"violations", c.violations},
          {"worst", number_or_null(c.worst)},
          {"worst_at", c.worst_at},
          {"first_violation_at", c.first_violation_at},
          {"documented_limit", c.documented_limit},
          {"allowed_worst", c.allowed_worst},
          {"failed", stress::failed(c)}};
}

}  // namespace

nlohmann::json stress_report_to_json(const stress::ModelStressReport& r) {
  nlohmann::json refusals = nlohmann::json::object();
  for (const auto& [status, tally] : r.refusals) {
    nlohmann::json t = {{"declared", tally.declared}, {"undeclared", tally.undeclared}};
    if (tally.undeclared > 0) t["first_undeclared_at"] = tally.first_undeclared_at;
    refusals[std::string(to_string(status))] = std::move(t);
  }
  nlohmann::json sweeps = nlohmann::json::array();
  for (const stress::SweepSummary& s : r.sweeps) {
    nlohmann::json excluded = nlohmann::json::array();
    for (const stress::ExcludedJump& e : s.excluded)
      excluded.push_back({{"name", e.name},
                          {"relative_jump", number_or_null(e.relative_jump)},
                          {"between", {e.from, e.to}}});
    sweeps.push_back({{"name", s.name},
                      {"coordinate", s.coordinate},
                      {"points", s.points},
                      {"chains", s.chains},
                      {"worst_relative_jump", number_or_null(s.worst_relative_jump)},
                      {"worst_between", {s.worst_from, s.worst_to}},
                      {"worst_wavelength_nm", s.worst_wavelength_nm},
                      {"worst_chain", s.worst_chain},
                      {"documented_jumps", std::move(excluded)}});
  }
  nlohmann::json trends = nlohmann::json::array();
  for (const stress::BoundCheck& t : r.trends) trends.push_back(check_to_json(t));
  return {{"model", r.model},
          {"version", r.version},
          {"wavelengths_nm", r.wavelengths_nm},
          {"options", r.options},
          {"samples", r.samples},
          {"models_built", r.models_built},
          {"refusals", std::move(refusals)},
          {"undeclared_refusals", r.undeclared_refusals()},
          {"non_finite_values", r.non_finite_values},
          {"negative_values", r.negative_values},
          {"sweeps", std::move(sweeps)},
          {"symmetry", check_to_json(r.symmetry)},
          {"energy", check_to_json(r.energy)},
          {"radiance_below_sun", check_to_json(r.radiance_below_sun)},
          {"trends", std::move(trends)},
          {"passed", stress::stress_passed(r)},
          {"seconds", r.seconds}};
}

}  // namespace clearsky::api
