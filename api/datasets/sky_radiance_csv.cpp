// CSV of the open sky-radiance format (sky_radiance_csv.h).
#include "api/datasets/sky_radiance_csv.h"

#include <array>
#include <optional>
#include <string>

#include "api/datasets/csv_lines.h"
#include "api/datasets/sky_radiance_rows.h"
#include "api/error/api_error.h"
#include "api/request/parameters.h"

namespace clearsky::api {
namespace {

constexpr std::array<std::string_view, 8> kColumns = {
    "time",        "latitude",     "longitude",     "elevation_m",
    "view_zenith", "view_azimuth", "wavelength_nm", "radiance"};

}  // namespace

std::vector<MeasuredCapture> parse_sky_radiance_csv(std::string_view text) {
  const std::vector<std::string_view> lines = csv_lines_of(text);
  if (lines.empty()) throw ApiError(400, "invalid_body", "body", "body: empty (no header line)");

  // Where each of kColumns is in a row.
  std::array<std::optional<std::size_t>, kColumns.size()> position;
  const std::vector<std::string_view> header = csv_fields_of(lines.front());
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
    const std::vector<std::string_view> fields = csv_fields_of(lines[l]);
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
