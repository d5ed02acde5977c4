// CSV of the open broadband irradiance format (irradiance_csv.h).
#include "api/datasets/irradiance_csv.h"

#include <array>
#include <optional>
#include <string>

#include "api/datasets/csv_lines.h"
#include "api/datasets/irradiance_rows.h"
#include "api/error/api_error.h"
#include "api/request/parameters.h"

namespace clearsky::api {
namespace {

enum Column { kTime, kLatitude, kLongitude, kElevation, kGhi, kDhi, kDni, kAveraging, kCount };
constexpr std::array<std::string_view, kCount> kColumns = {
    "time", "latitude", "longitude", "elevation_m", "ghi", "dhi", "dni", "averaging_s"};

}  // namespace

std::vector<storage::IrradianceSample> parse_irradiance_csv(std::string_view text) {
  const std::vector<std::string_view> lines = csv_lines_of(text);
  if (lines.empty()) throw ApiError(400, "invalid_body", "body", "body: empty (no header line)");

  std::array<std::optional<std::size_t>, kCount> position;
  const std::vector<std::string_view> header = csv_fields_of(lines.front());
  for (std::size_t f = 0; f < header.size(); ++f) {
    std::size_t c = 0;
    while (c < kColumns.size() && kColumns[c] != header[f]) ++c;
    const std::string name(header[f]);
    if (c == kColumns.size())
      throw ApiError(400, "invalid_body", name.empty() ? "body" : name,
                     "header (line 1): unknown column '" + name +
                         "'; the columns are time, latitude, longitude, elevation_m, ghi, dhi, "
                         "dni, averaging_s");
    if (position[c])
      throw ApiError(400, "invalid_body", name, "header (line 1): column " + name + " twice");
    position[c] = f;
  }
  for (std::size_t c : {kTime, kLatitude, kLongitude, kElevation})
    if (!position[c])
      throw ApiError(400, "invalid_body", std::string(kColumns[c]),
                     "header (line 1): no column " + std::string(kColumns[c]));
  if (!position[kGhi] && !position[kDhi] && !position[kDni])
    throw ApiError(400, "invalid_body", "ghi",
                   "header (line 1): no column ghi, dhi or dni (at least one is needed)");

  const CsvRowNames names;
  std::vector<IrradianceRow> rows;
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
    // An optional column, or an empty field of it: not measured.
    auto optional_number = [&](std::size_t c) -> std::optional<double> {
      if (!position[c] || fields[*position[c]].empty()) return std::nullopt;
      return number(c);
    };
    IrradianceRow r;
    r.time = std::string(fields[*position[kTime]]);
    r.latitude_deg = number(kLatitude);
    r.longitude_deg = number(kLongitude);
    r.elevation_m = number(kElevation);
    r.ghi_w_m2 = optional_number(kGhi);
    r.dhi_w_m2 = optional_number(kDhi);
    r.dni_w_m2 = optional_number(kDni);
    r.averaging_s = optional_number(kAveraging);
    rows.push_back(std::move(r));
  }
  return irradiance_samples(rows, names);
}

}  // namespace clearsky::api
