// CSV of the open broadband irradiance format (irradiance_csv.h).
#include "api/datasets/irradiance_csv.h"

#include <string>

#include "api/datasets/csv_columns.h"
#include "api/datasets/irradiance_rows.h"
#include "api/error/api_error.h"

namespace clearsky::api {
namespace {

enum Column { kTime, kLatitude, kLongitude, kElevation, kGhi, kDhi, kDni, kAveraging, kCount };

}  // namespace

std::vector<storage::IrradianceSample> parse_irradiance_csv(std::string_view text) {
  const CsvColumns columns(
      text, {"time", "latitude", "longitude", "elevation_m", "ghi", "dhi", "dni", "averaging_s"});
  for (std::size_t c : {kTime, kLatitude, kLongitude, kElevation}) columns.require(c);
  if (!columns.has(kGhi) && !columns.has(kDhi) && !columns.has(kDni))
    throw ApiError(400, "invalid_body", "ghi",
                   "header (line 1): no column ghi, dhi or dni (at least one is needed)");

  std::vector<IrradianceRow> rows;
  rows.reserve(columns.row_count());
  for (std::size_t i = 0; i < columns.row_count(); ++i) {
    const CsvRow row = columns.row(i);
    IrradianceRow r;
    r.time = std::string(row.text(kTime));
    r.latitude_deg = row.number(kLatitude);
    r.longitude_deg = row.number(kLongitude);
    r.elevation_m = row.number(kElevation);
    // An optional column, or an empty field of it: not measured.
    r.ghi_w_m2 = row.optional_number(kGhi);
    r.dhi_w_m2 = row.optional_number(kDhi);
    r.dni_w_m2 = row.optional_number(kDni);
    r.averaging_s = row.optional_number(kAveraging);
    rows.push_back(std::move(r));
  }
  return irradiance_samples(rows, columns.names());
}

}  // namespace clearsky::api
