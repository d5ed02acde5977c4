// CSV of the open sky-radiance format (sky_radiance_csv.h).
#include "api/datasets/sky_radiance_csv.h"

#include <array>
#include <optional>
#include <string>

#include "api/datasets/sky_radiance_rows.h"
#include "api/error/api_error.h"
#include "api/request/parameters.h"

namespace clearsky::api {
namespace {

constexpr std::array<std::string_view, 8> kColumns = {
    "time",        "latitude",     "longitude",     "elevation_m",
    "view_zenith", "view_azimuth", "wavelength_nm", "radiance"};

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// Data row i (0-based) is on line i + 2.
class CsvRowNames : public SkyRadianceRowNames {
 public:
  std::string member(std::size_t, const std::string& name) const override { return name; }
  std::string where(std::size_t row) const override {
    return "row " + std::to_string(row + 1) + " (line " + std::to_string(row + 2) + ")";
  }
};

// The lines of the text without their ends; trailing blank lines dropped.
std::vector<std::string_view> lines_of(std::string_view text) {
  std::vector<std::string_view> lines;
  while (!text.empty()) {
    const auto end = text.find('\n');
    std::string_view line = text.substr(0, end);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
  }
  while (!lines.empty() && trim(lines.back()).empty()) lines.pop_back();
  return lines;
}

std::vector<std::string_view> fields_of(std::string_view line) {
  std::vector<std::string_view> fields;
  for (;;) {
    const auto comma = line.find(',');
    fields.push_back(trim(line.substr(0, comma)));
    if (comma == std::string_view::npos) return fields;
    line.remove_prefix(comma + 1);
  }
}

}  // namespace

std::vector<MeasuredCapture> parse_sky_radiance_csv(std::string_view text) {
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (text.starts_with(kByteOrderMark)) text.remove_prefix(kByteOrderMark.size());
  const std::vector<std::string_view> lines = lines_of(text);
  if (lines.empty()) throw ApiError(400, "invalid_body", "body", "body: empty (no header line)");

  // Where each of kColumns is in a row.
  std::array<std::optional<std::size_t>, kColumns.size()> position;
  const std::vector<std::string_view> header = fields_of(lines.front());
  for (std::size_t f = 0; f < header.size(); ++f) {
    std::size_t c = 0;
    while (c < kColumns.size() && kColumns[c] != header[f]) ++c;
    const std::string name(header[f]);
    if (c == kColumns.size())
      throw ApiError(400, "invalid_body", name.empty() ? "body" : name,
                     "header (line 1): unknown column '" + name +
                         "'; the columns are time, latitude, longitude, elevation_m, view_zenith, "
                         "view_azimuth, wavelength_nm, radiance");
    if (position[c])
      throw ApiError(400, "invalid_body", name, "header (line 1): column " + name + " twice");
    position[c] = f;
  }
  for (std::size_t c = 0; c < kColumns.size(); ++c)
    if (!position[c])
      throw ApiError(400, "invalid_body", std::string(kColumns[c]),
                     "header (line 1): no column " + std::string(kColumns[c]));

  const CsvRowNames names;
  std::vector<SkyRadianceRow> rows;
  rows.reserve(lines.size() - 1);
  for (std::size_t l = 1; l < lines.size(); ++l) {
    const std::size_t row = l - 1;
    const std::vector<std::string_view> fields = fields_of(lines[l]);
    if (fields.size() != header.size())
      throw ApiError(400, "invalid_body", "body",
                     names.where(row) + ": " + std::to_string(fields.size()) +
                         " fields, the header has " + std::to_string(header.size()));
    auto number = [&](std::size_t c) {
      const std::string column(kColumns[c]);
      try {
        return number_value(column, fields[*position[c]]);
      } catch (const ApiError& e) {
        throw ApiError(400, "invalid_body", column,
                       names.where(row) + ", " + column + ": " + e.reason());
      }
    };
    SkyRadianceRow r;
    r.time = std::string(fields[*position[0]]);
    r.latitude_deg = number(1);
    r.longitude_deg = number(2);
    r.elevation_m = number(3);
    r.view_zenith_deg = number(4);
    r.view_azimuth_deg = number(5);
    r.wavelength_nm = number(6);
    r.radiance_w_m2_sr_nm = number(7);
    rows.push_back(std::move(r));
  }
  return sky_radiance_captures(rows, names);
}

}  // namespace clearsky::api
