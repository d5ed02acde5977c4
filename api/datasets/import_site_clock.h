// Where and on which clock the captures of a Kider-style archive were taken: the archive's
// file names give the local time of the site and nothing else (Kider et al. 2014, ACM TOG
// 33(6)), so an import is told the site and the UTC offset (docs/data-api.md "Site and clock of
// an archive"). The parameters are those of the upload, the path import and `clearsky import
// kider` alike:
//   lat        site latitude, North positive (decimal or DMS, api/parse/coordinates.h)
//   lon        site longitude, East positive
//   elevation  site elevation above sea level, m, in [-500, 9000]
//   utc_offset local time minus UTC of the file names' clock: Z, +hh:mm, +hhmm or +hh
// Each defaults to the published captures' values (roof of Rhodes Hall, Cornell University,
// EDT = UTC-04:00), so that an import without them reads those as before. They are stored with
// each capture and give its sun position (models/evaluation/capture_preparation.h).
#pragma once

#include "api/request/parameters.h"
#include "storage/importers/kider_format.h"

namespace clearsky::api {

// Reads lat, lon, elevation and utc_offset (400 naming the one out of range).
storage::KiderImportOptions parse_import_site_clock(Parameters& parameters);

// Whether any of the four is present (without reading it).
bool has_import_site_clock(const Parameters& parameters);

}  // namespace clearsky::api
