// The columns of the open formats' CSV (csv_columns.h).
#include "api/datasets/csv_columns.h"

#include <utility>

#include "api/error/api_error.h"
#include "api/request/parameters.h"

namespace clearsky::api {

std::string_view CsvRow::text(std::size_t column) const {
  const auto& position = columns_->position_[column];
  return position ? fields_[*position] : std::string_view{};
}

double CsvRow::number(std::size_t column) const {
  const std::string name(columns_->names_of_columns_[column]);
  try {
    return number_value(name, text(column));
  } catch (const ApiError& e) {
    throw ApiError(400, "invalid_body", name,
                   columns_->names_.where(row_) + ", " + name + ": " + e.reason());
  }
}

std::optional<double> CsvRow::optional_number(std::size_t column) const {
  if (!columns_->has(column) || text(column).empty()) return std::nullopt;
  return number(column);
}

CsvColumns::CsvColumns(std::string_view text, std::vector<std::string_view> names)
    : lines_(csv_lines_of(text)),
      names_of_columns_(std::move(names)),
      position_(names_of_columns_.size()) {
  if (lines_.empty()) throw ApiError(400, "invalid_body", "body", "body: empty (no header line)");
  std::string listed;
  for (const std::string_view name : names_of_columns_)
    listed += (listed.empty() ? "" : ", ") + std::string(name);
  const std::vector<std::string_view> header = csv_fields_of(lines_.front());
  field_count_ = header.size();
  for (std::size_t f = 0; f < header.size(); ++f) {
    std::size_t c = 0;
    while (c < names_of_columns_.size() && names_of_columns_[c] != header[f]) ++c;
    const std::string name(header[f]);
    if (c == names_of_columns_.size())
      throw ApiError(400, "invalid_body", name.empty() ? "body" : name,
                     "header (line 1): unknown column '" + name + "'; the columns are " + listed);
    if (position_[c])
      throw ApiError(400, "invalid_body", name, "header (line 1): column " + name + " twice");
    position_[c] = f;
  }
}

void CsvColumns::require(std::size_t column) const {
  if (!has(column)) {
    const std::string name(names_of_columns_[column]);
    throw ApiError(400, "invalid_body", name, "header (line 1): no column " + name);
  }
}

CsvRow CsvColumns::row(std::size_t i) const {
  std::vector<std::string_view> fields = csv_fields_of(lines_[i + 1]);
  if (fields.size() != field_count_)
    throw ApiError(400, "invalid_body", "body",
                   names_.where(i) + ": " + std::to_string(fields.size()) +
                       " fields, the header has " + std::to_string(field_count_));
  return CsvRow(*this, i, std::move(fields));
}

}  // namespace clearsky::api
