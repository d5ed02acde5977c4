// Reads the parameter tables written for people (the comment table of
// models/atmosphere/atmosphere_parameters.h, each model's header or README table) so that tests
// compare them with the declarations the code uses (atmosphere_parameter_table.h, the model
// descriptors) and the prose cannot drift.
//
// A table is a run of lines holding "| a | b | ... |" (after an optional "// "), whose first row
// names the columns; the separator row (---) is skipped, and so are continuation rows (empty
// first cell). Cells: unit "-" is dimensionless; a default is a number or a word ("grass"); a
// range is the first "[a, b]", "(a, b]", "[a, b)", "(a, b)" or "{a, b}" (the integers a..b) in
// its cell, "inf" for infinity.
#pragma once

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace clearsky::testing {

// The repository's root, found from this header's path (CMake compiles with absolute paths, or
// with paths relative to build/tests when ccache rewrites them).
inline std::filesystem::path source_root() {
  std::filesystem::path here(__FILE__);
  if (here.is_relative()) here = std::filesystem::path(CLEARSKY_BINARY_DIR) / "tests" / here;
  return std::filesystem::weakly_canonical(here)
      .parent_path()
      .parent_path()
      .parent_path()
      .parent_path();
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

struct TableRange {
  double min = 0, max = 0;
  bool min_exclusive = false, max_exclusive = false;
  int min_decimals = 0, max_decimals = 0;  // digits after the point as written
};

struct TableRow {
  std::map<std::string, std::string> cells;  // by column name
  const std::string& at(const std::string& column) const {
    static const std::string empty;
    auto it = cells.find(column);
    return it == cells.end() ? empty : it->second;
  }
};

inline std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

inline std::vector<std::string> split_cells(const std::string& line) {
  // line starts and ends with '|'.
  std::vector<std::string> cells;
  std::size_t begin = 1;
  while (true) {
    const std::size_t end = line.find('|', begin);
    if (end == std::string::npos) break;
    cells.push_back(trim(line.substr(begin, end - begin)));
    begin = end + 1;
  }
  return cells;
}

// The first table of text whose first column is named first_column.
inline std::vector<TableRow> read_table(const std::string& text, const std::string& first_column) {
  std::vector<TableRow> rows;
  std::vector<std::string> columns;
  std::istringstream in(text);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    std::string body = trim(line);
    if (body.rfind("//", 0) == 0) body = trim(body.substr(2));
    if (body.size() < 2 || body.front() != '|' || body.back() != '|') {
      if (inside) break;
      continue;
    }
    const std::vector<std::string> cells = split_cells(body);
    if (!inside) {
      if (cells.empty() || cells[0] != first_column) continue;
      columns = cells;
      inside = true;
      continue;
    }
    if (cells.empty() || cells[0].empty() || cells[0].rfind("---", 0) == 0) continue;
    TableRow row;
    for (std::size_t i = 0; i < cells.size() && i < columns.size(); ++i)
      row.cells[columns[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}

inline int decimals_of(const std::string& number) {
  const auto dot = number.find('.');
  if (dot == std::string::npos) return 0;
  const auto e = number.find_first_of("eE", dot);
  return static_cast<int>((e == std::string::npos ? number.size() : e) - dot - 1);
}

inline double number_of(const std::string& text) {
  const std::string t = trim(text);
  if (t == "inf") return std::numeric_limits<double>::infinity();
  if (t == "-inf") return -std::numeric_limits<double>::infinity();
  std::size_t used = 0;
  const double v = std::stod(t, &used);
  if (used != t.size()) throw std::invalid_argument("not a number: " + t);
  return v;
}

inline std::optional<TableRange> range_of(const std::string& cell) {
  const auto open = cell.find_first_of("[({");
  if (open == std::string::npos) return std::nullopt;
  const auto close = cell.find_first_of("])}", open);
  const auto comma = cell.find(',', open);
  if (close == std::string::npos || comma == std::string::npos || comma > close)
    return std::nullopt;
  TableRange r;
  const std::string lo = trim(cell.substr(open + 1, comma - open - 1));
  const std::string hi = trim(cell.substr(comma + 1, close - comma - 1));
  r.min = number_of(lo);
  r.max = number_of(hi);
  r.min_decimals = decimals_of(lo);
  r.max_decimals = decimals_of(hi);
  r.min_exclusive = cell[open] == '(';
  r.max_exclusive = cell[close] == ')';
  return r;
}

// Whether written (with `decimals` digits after the point) is value rounded.
inline bool matches_as_written(double written, int decimals, double value) {
  if (std::isinf(written) || std::isinf(value)) return written == value;
  return std::abs(written - value) <=
         0.5 * std::pow(10.0, -decimals) * (1 + 1e-9) + 1e-12 * std::abs(value);
}

inline std::string unit_of(const std::string& cell) { return cell == "-" ? "" : cell; }

}  // namespace clearsky::testing
