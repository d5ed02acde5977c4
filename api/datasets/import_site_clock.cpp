// The site and clock of an archive import (import_site_clock.h).
#include "api/datasets/import_site_clock.h"

#include "api/parse/coordinates.h"
#include "api/parse/iso8601_time.h"

namespace clearsky::api {

// Site elevations of the ground stations that measure skies: from the Dead Sea shore (-430 m)
// to the highest observatories (about 5,600 m), with room on both sides.
constexpr double kMinSiteElevationM = -500.0;
constexpr double kMaxSiteElevationM = 9000.0;

storage::KiderImportOptions parse_import_site_clock(Parameters& parameters) {
  storage::KiderImportOptions options;
  if (const auto lat = parameters.text("lat")) options.site.latitude_deg = parse_latitude(*lat);
  if (const auto lon = parameters.text("lon")) options.site.longitude_deg = parse_longitude(*lon);
  options.site.elevation_m = parameters.number_or("elevation", options.site.elevation_m,
                                                  kMinSiteElevationM, kMaxSiteElevationM);
  if (const auto offset = parameters.text("utc_offset"))
    options.utc_offset_minutes = parse_utc_offset_minutes(*offset, "utc_offset");
  return options;
}

bool has_import_site_clock(const Parameters& parameters) {
  return parameters.has_any({"lat", "lon", "elevation", "utc_offset"});
}

}  // namespace clearsky::api
