// CSV of the open sky-radiance format (sky_radiance_csv.h).
#include "api/datasets/sky_radiance_csv.h"

#include <string>

#include "api/datasets/csv_columns.h"
#include "api/datasets/sky_radiance_rows.h"

namespace clearsky::api {
namespace {

enum Column {
  kTime,
  kLatitude,
  kLongitude,
  kElevation,
  kViewZenith,
  kViewAzimuth,
  kWavelength,
  kRadiance,
  kCount
};

}  // namespace

std::vector<MeasuredCapture> parse_sky_radiance_csv(std::string_view text) {
  const CsvColumns columns(text, {"time", "latitude", "longitude", "elevation_m", "view_zenith",
                                  "view_azimuth", "wavelength_nm", "radiance"});
  // Every column is required.
  for (std::size_t c = 0; c < kCount; ++c) columns.require(c);

  std::vector<SkyRadianceRow> rows;
  rows.reserve(columns.row_count());
  for (std::size_t i = 0; i < columns.row_count(); ++i) {
    const CsvRow row = columns.row(i);
    SkyRadianceRow r;
    r.time = std::string(row.text(kTime));
    r.latitude_deg = row.number(kLatitude);
    r.longitude_deg = row.number(kLongitude);
    r.elevation_m = row.number(kElevation);
    r.view_zenith_deg = row.number(kViewZenith);
    r.view_azimuth_deg = row.number(kViewAzimuth);
    r.wavelength_nm = row.number(kWavelength);
    r.radiance_w_m2_sr_nm = row.number(kRadiance);
    rows.push_back(std::move(r));
  }
  return sky_radiance_captures(rows, columns.names());
}

}  // namespace clearsky::api
