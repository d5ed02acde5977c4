// The quality tables of models/quality/ (docs/quality-levels.md): parsing and lookup.
#include "models/quality/quality_levels.h"

#include <charconv>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "models/core/embedded_data.h"

namespace clearsky {

namespace {

constexpr std::string_view kHeader =
    "level,options,p95_relative_error,max_relative_error,build_seconds,table_bytes";

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = text.find(separator, begin);
    parts.push_back(text.substr(begin, end == std::string_view::npos ? end : end - begin));
    if (end == std::string_view::npos) return parts;
    begin = end + 1;
  }
}

std::invalid_argument table_error(std::size_t line, const std::string& reason) {
  return std::invalid_argument("quality table, line " + std::to_string(line) + ": " + reason);
}

double number(std::string_view text, std::size_t line) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() ||
      !std::isfinite(value)) {
    throw table_error(line, "'" + std::string(text) + "' is not a number");
  }
  return value;
}

std::optional<double> optional_number(std::string_view text, std::size_t line) {
  if (text.empty()) return std::nullopt;
  return number(text, line);
}

}  // namespace

std::string_view to_string(QualityLevel level) {
  switch (level) {
    case QualityLevel::draft:
      return "draft";
    case QualityLevel::standard:
      return "standard";
    case QualityLevel::reference:
      return "reference";
  }
  return "standard";
}

std::optional<QualityLevel> parse_quality_level(std::string_view text) {
  for (QualityLevel level : kQualityLevels) {
    if (to_string(level) == text) return level;
  }
  return std::nullopt;
}

std::array<QualitySetting, 3> parse_quality_table(std::string_view text) {
  std::array<QualitySetting, 3> rows;
  std::array<bool, 3> seen{};
  bool header = false;
  std::size_t line_number = 0;
  for (std::string_view line : split(text, '\n')) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty() || line.front() == '#') continue;
    if (!header) {
      if (line != kHeader)
        throw table_error(line_number, "the header must be " + std::string(kHeader));
      header = true;
      continue;
    }
    const auto columns = split(line, ',');
    if (columns.size() != 6) throw table_error(line_number, "6 columns expected");
    const auto level = parse_quality_level(columns[0]);
    if (!level) throw table_error(line_number, "unknown level '" + std::string(columns[0]) + "'");
    const auto index = static_cast<std::size_t>(*level);
    if (seen[index]) throw table_error(line_number, "level " + std::string(columns[0]) + " twice");
    seen[index] = true;
    QualitySetting& row = rows[index];
    row.level = *level;
    if (!columns[1].empty()) {
      for (std::string_view item : split(columns[1], ';')) {
        const auto name_value = split(item, '=');
        if (name_value.size() != 2 || name_value[0].empty())
          throw table_error(line_number, "options are name=value separated by ';'");
        if (!row.options.emplace(std::string(name_value[0]), number(name_value[1], line_number))
                 .second)
          throw table_error(line_number, "option " + std::string(name_value[0]) + " twice");
      }
    }
    row.p95_relative_error = optional_number(columns[2], line_number);
    row.max_relative_error = optional_number(columns[3], line_number);
    row.build_seconds = optional_number(columns[4], line_number);
    row.table_bytes = optional_number(columns[5], line_number);
  }
  if (!header) throw table_error(line_number, "no header");
  for (QualityLevel level : kQualityLevels) {
    if (!seen[static_cast<std::size_t>(level)])
      throw table_error(line_number, "level " + std::string(to_string(level)) + " missing");
  }
  return rows;
}

std::optional<std::string_view> embedded_quality_table(std::string_view model_id) {
  // models/data is the embedding root (models/CMakeLists.txt); the tables sit beside it.
  const std::string path = "../quality/" + std::string(model_id) + ".csv";
  for (const data::EmbeddedFile& file : data::embedded_files()) {
    if (file.path == path) return file.content;
  }
  return std::nullopt;
}

const std::array<QualitySetting, 3>& quality_table(std::string_view model_id) {
  static std::mutex mutex;
  static std::unordered_map<std::string, std::array<QualitySetting, 3>> tables;
  const std::lock_guard lock(mutex);
  const std::string id(model_id);
  auto found = tables.find(id);
  if (found == tables.end()) {
    std::array<QualitySetting, 3> table;
    if (const auto text = embedded_quality_table(id)) {
      table = parse_quality_table(*text);
    } else {
      for (QualityLevel level : kQualityLevels)
        table[static_cast<std::size_t>(level)].level = level;
    }
    found = tables.emplace(id, std::move(table)).first;
  }
  return found->second;  // never erased: references stay valid
}

const QualitySetting& quality_setting(std::string_view model_id, QualityLevel level) {
  return quality_table(model_id)[static_cast<std::size_t>(level)];
}

std::vector<std::string> apply_quality_level(const ModelDescriptor& descriptor,
                                             const QualitySetting& setting,
                                             std::map<std::string, double>& options) {
  std::vector<std::string> overridden;
  for (const auto& [name, value] : setting.options) {
    const auto given = options.find(name);
    if (given != options.end()) {
      if (given->second != value) overridden.push_back(name);
      continue;
    }
    const ParameterSpec* spec = nullptr;
    for (const ParameterSpec& p : descriptor.parameters) {
      if (p.name == name) spec = &p;
    }
    if (spec == nullptr) {
      throw std::logic_error("quality table of " + descriptor.id + " lists option " + name +
                             ", which its descriptor does not");
    }
    if (value != spec->default_value) options[name] = value;
  }
  return overridden;
}

std::map<std::string, double> resolved_quality_options(
    const QualitySetting& setting, const std::map<std::string, double>& options) {
  std::map<std::string, double> out;
  for (const auto& [name, value] : setting.options) {
    const auto given = options.find(name);
    out[name] = given != options.end() ? given->second : value;
  }
  return out;
}

}  // namespace clearsky
