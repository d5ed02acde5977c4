// Conversion of the parameters stored before schema version 4 (legacy_run_parameters.h).
#include "storage/schema/legacy_run_parameters.h"

#include <sqlite3.h>

#include <array>
#include <charconv>
#include <optional>

#include "models/atmosphere/atmosphere_parameters.h"

namespace clearsky::storage {
namespace {

struct AtmosphereKey {
  std::string_view key;   // as in AtmosphereParameters::canonical_string()
  std::string_view name;  // as in requests (api/request/sky_request.h)
  double AtmosphereParameters::*field;
};

constexpr std::array<AtmosphereKey, 10> kAtmosphereKeys = {{
    {"R", "earth_radius_m", &AtmosphereParameters::earth_radius_m},
    {"top", "top_radius_m", &AtmosphereParameters::top_radius_m},
    {"HR", "rayleigh_scale_height_m", &AtmosphereParameters::rayleigh_scale_height_m},
    {"HM", "mie_scale_height_m", &AtmosphereParameters::mie_scale_height_m},
    {"T", "rayleigh_temperature_celsius", &AtmosphereParameters::rayleigh_temperature_celsius},
    {"alpha", "alpha", &AtmosphereParameters::angstrom_alpha},
    {"beta", "beta", &AtmosphereParameters::angstrom_beta},
    {"ssa", "mie_single_scattering_albedo", &AtmosphereParameters::mie_single_scattering_albedo},
    {"g", "g", &AtmosphereParameters::mie_phase_g},
    {"turbidity", "turbidity", &AtmosphereParameters::turbidity},
}};

std::optional<double> number(std::string_view text) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// The shortest decimal that reads back to the same double (std::to_chars without precision).
std::string shortest(double value) {
  char text[32];
  const auto written = std::to_chars(text, text + sizeof text, value);
  return std::string(text, written.ptr);
}

bool is_identifier(std::string_view name) {
  if (name.empty()) return false;
  for (char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'))
      return false;
  return true;
}

void legacy_run_parameters_sql(sqlite3_context* context, int, sqlite3_value** arguments) {
  const unsigned char* text = sqlite3_value_text(arguments[0]);
  const std::string json = legacy_run_parameters_json(
      text == nullptr ? std::string_view() : reinterpret_cast<const char*>(text));
  sqlite3_result_text(context, json.c_str(), static_cast<int>(json.size()), SQLITE_TRANSIENT);
}

}  // namespace

std::string legacy_run_parameters_json(std::string_view canonical) {
  const AtmosphereParameters defaults;
  std::string json;
  const auto add = [&](std::string_view name, const std::string& value) {
    json += json.empty() ? '{' : ',';
    json += '"';
    json.append(name);
    json += "\":";
    json += value;
  };
  while (!canonical.empty()) {
    const std::size_t semicolon = canonical.find(';');
    const std::string_view pair = canonical.substr(0, semicolon);
    canonical =
        semicolon == std::string_view::npos ? std::string_view() : canonical.substr(semicolon + 1);
    const std::size_t equals = pair.find('=');
    if (equals == std::string_view::npos) return "{}";
    const std::string_view key = pair.substr(0, equals);
    const std::string_view value = pair.substr(equals + 1);
    if (key == "grid") continue;  // evaluations always ran on the paper's grid
    if (key == "albedo") {
      if (value == "grass") continue;
      const auto albedo = number(value);
      if (!albedo) return "{}";
      add("albedo", shortest(*albedo));
      continue;
    }
    const auto parsed = number(value);
    if (!parsed || !is_identifier(key)) return "{}";
    bool atmosphere = false;
    for (const AtmosphereKey& k : kAtmosphereKeys) {
      if (k.key != key) continue;
      atmosphere = true;
      if (*parsed != defaults.*k.field) add(k.name, shortest(*parsed));
    }
    if (!atmosphere) add(key, shortest(*parsed));
  }
  return json.empty() ? "{}" : json + "}";
}

void register_legacy_run_parameters(Database& db) {
  const int code = sqlite3_create_function(db.handle(), "legacy_run_parameters_json", 1,
                                           SQLITE_UTF8 | SQLITE_DETERMINISTIC, nullptr,
                                           legacy_run_parameters_sql, nullptr, nullptr);
  if (code != SQLITE_OK)
    throw SqliteError(code, "cannot register legacy_run_parameters_json: " +
                                std::string(sqlite3_errmsg(db.handle())));
}

}  // namespace clearsky::storage
