// The lines and fields of the open formats' CSV (docs/measurement-formats.md; RFC 4180 without
// quoting, which no member needs): lines end with LF or CRLF, trailing blank lines are dropped,
// a UTF-8 byte order mark is skipped; fields are separated by commas and trimmed of spaces and
// tabs. Shared by the sky-radiance CSV (sky_radiance_csv.h) and the irradiance CSV
// (irradiance_csv.h).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "api/datasets/sky_radiance_rows.h"

namespace clearsky::api {

std::string_view trim_csv_field(std::string_view s);

// The lines of the text without their ends (and without a leading byte order mark); trailing
// blank lines dropped.
std::vector<std::string_view> csv_lines_of(std::string_view text);

std::vector<std::string_view> csv_fields_of(std::string_view line);

// How refusals name a CSV row's member: the column, with "row 12 (line 13)" (data row i,
// 0-based, is on line i + 2, after the header).
class CsvRowNames : public SkyRadianceRowNames {
 public:
  std::string member(std::size_t, const std::string& name) const override { return name; }
  std::string where(std::size_t row) const override {
    return "row " + std::to_string(row + 1) + " (line " + std::to_string(row + 2) + ")";
  }
};

}  // namespace clearsky::api
