// The columns of a CSV file of the open measurement formats (docs/measurement-formats.md; lines
// and fields as csv_lines.h): a header naming each of the format's columns at most once, in any
// order, then one row per line with as many fields as the header. Shared by the sky-radiance CSV
// (sky_radiance_csv.h) and the irradiance CSV (irradiance_csv.h), which say which columns are
// required and read their rows' values through CsvRow. Refusals are 400 invalid_body naming the
// column (or body), with the row and its line (CsvRowNames).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "api/datasets/csv_lines.h"

namespace clearsky::api {

class CsvColumns;

// The fields of one data row, by the format's column index.
class CsvRow {
 public:
  // The field as written ("" for a column the header does not have).
  std::string_view text(std::size_t column) const;
  // The field as a number (400 naming the column, with the row).
  double number(std::size_t column) const;
  // A column the header may lack, or an empty field: nothing (a value not measured).
  std::optional<double> optional_number(std::size_t column) const;

 private:
  friend class CsvColumns;
  CsvRow(const CsvColumns& columns, std::size_t row, std::vector<std::string_view> fields)
      : columns_(&columns), row_(row), fields_(std::move(fields)) {}
  const CsvColumns* columns_;
  std::size_t row_;  // 0-based data row
  std::vector<std::string_view> fields_;
};

// The file's header and data lines. Holds views of the text, which must outlive it.
class CsvColumns {
 public:
  // names: the format's columns (their order is the index CsvRow reads them by, and the list an
  // unknown column's refusal gives). Refuses an empty file, an unknown column, a column twice.
  CsvColumns(std::string_view text, std::vector<std::string_view> names);

  // Refuses a header without the column (400 naming it).
  void require(std::size_t column) const;
  bool has(std::size_t column) const { return position_[column].has_value(); }

  std::size_t row_count() const { return lines_.size() - 1; }
  // Data row i (0-based); refuses a row whose field count is not the header's.
  CsvRow row(std::size_t i) const;
  const CsvRowNames& names() const { return names_; }

 private:
  friend class CsvRow;
  std::vector<std::string_view> lines_;
  std::vector<std::string_view> names_of_columns_;
  std::vector<std::optional<std::size_t>> position_;  // of each column in a row
  std::size_t field_count_ = 0;
  CsvRowNames names_;
};

}  // namespace clearsky::api
