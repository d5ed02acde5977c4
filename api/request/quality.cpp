// The quality parameter: parsing, applying the level, and stating it in the answer.
#include "api/request/quality.h"

#include <sstream>

#include "api/http/api_types.h"
#include "api/request/quality_statement.h"

namespace clearsky::api {

namespace {

// The figures of the level that answered, for its own setting: none when the request changed
// one of its options. A reference with figures of its own was checked against a finer setting
// (docs/quality-levels.md); one without is the model's own converged setting, 0 against itself.
nlohmann::json error_json(const RequestQuality& quality, QualityLevel served) {
  if (!quality.overridden.empty()) return nullptr;
  const QualitySetting& row = quality_setting(quality.model_id, served);
  const bool checked_reference =
      served == QualityLevel::reference && row.max_relative_error.value_or(0.0) > 0.0;
  nlohmann::json out = {{"against", checked_reference ? "finer_setting" : "reference"}};
  out["p95_relative"] = row.p95_relative_error ? finite(*row.p95_relative_error) : nullptr;
  out["max_relative"] = row.max_relative_error ? finite(*row.max_relative_error) : nullptr;
  return out;
}

}  // namespace

RequestQuality parse_quality(Parameters& p, const ModelDescriptor& descriptor, ModelConfig& config,
                             QualityLevel default_level) {
  RequestQuality out;
  out.model_id = descriptor.id;
  const std::string text =
      p.choice("quality", {"draft", "standard", "reference"}, to_string(default_level));
  out.level = *parse_quality_level(text);
  out.table_row = &quality_setting(descriptor.id, out.level);
  out.overridden = apply_quality_level(descriptor, *out.table_row, config.options);
  out.setting = resolved_quality_options(*out.table_row, config.options);
  return out;
}

void add_quality_members(nlohmann::json& body, const RequestQuality& quality, QualityLevel served) {
  body["quality"] = to_string(quality.level);
  body["served_quality"] = to_string(served);
  nlohmann::json setting = nlohmann::json::object();
  const std::map<std::string, double> used =
      served == quality.level
          ? quality.setting
          : resolved_quality_options(quality_setting(quality.model_id, served), {});
  for (const auto& [name, value] : used) setting[name] = finite(value);
  body["quality_setting"] = std::move(setting);
  body["quality_error"] = error_json(quality, served);
  if (!quality.overridden.empty()) body["quality_overridden"] = quality.overridden;
}

void add_quality_headers(std::vector<std::pair<std::string, std::string>>& headers,
                         const RequestQuality& quality, QualityLevel served) {
  headers.emplace_back("Clearsky-Quality", std::string(to_string(quality.level)));
  headers.emplace_back("Clearsky-Served-Quality", std::string(to_string(served)));
  headers.emplace_back("Clearsky-Quality-Detail", quality_statement(quality, served).summary);
  // An answer from a cheaper level than asked changes once the asked level's tables are built:
  // no cache may keep it (the route's caching policy leaves a Cache-Control set here alone).
  if (served != quality.level) headers.emplace_back("Cache-Control", "no-store");
}

std::string quality_summary(const RequestQuality& quality, QualityLevel served) {
  std::ostringstream out;
  out.precision(6);
  out << "quality=" << to_string(quality.level) << "; served_quality=" << to_string(served)
      << "; setting=";
  const std::map<std::string, double> used =
      served == quality.level
          ? quality.setting
          : resolved_quality_options(quality_setting(quality.model_id, served), {});
  bool first = true;
  for (const auto& [name, value] : used) {
    out << (first ? "" : ",") << name << '=' << value;
    first = false;
  }
  if (first) out << "(none)";
  const QualitySetting& row = quality_setting(quality.model_id, served);
  if (!quality.overridden.empty()) {
    out << "; error=not stated (options overridden)";
  } else {
    if (row.p95_relative_error) out << "; p95_relative_error=" << *row.p95_relative_error;
    if (row.max_relative_error) out << "; max_relative_error=" << *row.max_relative_error;
  }
  return out.str();
}

}  // namespace clearsky::api
