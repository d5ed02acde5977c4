// The quality levels of each model (docs/quality-levels.md): draft, standard and reference, each
// a set of the model's cost options with its measured error against the reference level. The
// tables are data only, one file per model (models/quality/<id>.csv, compiled into the library
// like models/data): a header line, one row per level,
//
//   level,options,p95_relative_error,max_relative_error,build_seconds,table_bytes
//   draft,table_r_size=8;table_mu_size=32,0.012,0.05,2.2,4800000
//
// options `name=value` separated by ';' (empty for a model without cost options), figures empty
// where not measured; lines starting with '#' are comments (how the figures were measured).
// standard is the model's defaults (the 2016 study's setting), so its answers are those of a
// request without quality.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "models/core/model_descriptor.h"

namespace clearsky {

enum class QualityLevel { draft, standard, reference };

inline constexpr std::array<QualityLevel, 3> kQualityLevels = {
    QualityLevel::draft, QualityLevel::standard, QualityLevel::reference};

std::string_view to_string(QualityLevel level);
// "draft", "standard" or "reference"; nullopt otherwise.
std::optional<QualityLevel> parse_quality_level(std::string_view text);

// One row of a model's table.
struct QualitySetting {
  QualityLevel level = QualityLevel::standard;
  std::map<std::string, double> options;  // the level's value of each cost option it lists
  // Against the model's reference level, over the suns, views and wavelengths of
  // tools/quality/measure_quality_levels.py; 0 for the reference itself.
  std::optional<double> p95_relative_error;
  std::optional<double> max_relative_error;
  std::optional<double> build_seconds;  // the level's table build, 40 wavelengths (see its CSV)
  std::optional<double> table_bytes;    // its tables' bytes, 40 wavelengths
};

// The three rows of one table's text, in the order draft, standard, reference. Throws
// std::invalid_argument naming the line for a malformed table (a missing or repeated level, a
// value that is not a number, a column missing).
std::array<QualitySetting, 3> parse_quality_table(std::string_view text);

// The text of the model's embedded table (models/quality/<id>.csv); nullopt when it has none.
std::optional<std::string_view> embedded_quality_table(std::string_view model_id);
// The model's table, parsed once. A model without one (every registered model has one, as
// tests/models/quality/quality_levels_test.cpp checks; the test models of the unit tests do not)
// has no cost options: every level is its defaults, without error figures.
const std::array<QualitySetting, 3>& quality_table(std::string_view model_id);
const QualitySetting& quality_setting(std::string_view model_id, QualityLevel level);

// The level applied to a model's options: each option of the level that `options` does not set
// already (a request's explicit value wins) is set, unless it equals the descriptor's default
// (so that standard leaves the options, hence every cache key, as they were). Returns the
// level's option names the request had set itself with another value (the overridden ones).
std::vector<std::string> apply_quality_level(const ModelDescriptor& descriptor,
                                             const QualitySetting& setting,
                                             std::map<std::string, double>& options);

// The value of every option the level lists, as the model will be built with it: the request's
// explicit value where given, else the level's.
std::map<std::string, double> resolved_quality_options(
    const QualitySetting& setting, const std::map<std::string, double>& options);

}  // namespace clearsky
