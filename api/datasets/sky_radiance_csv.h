// The CSV form of the open sky-radiance format (docs/measurement-formats.md; RFC 4180 without
// quoting, which no member needs): a header naming the columns time, latitude, longitude,
// elevation_m, view_zenith, view_azimuth, wavelength_nm and radiance in any order, then one
// row per measured value. Lines end with LF or CRLF; blank lines only at the end; a UTF-8 byte
// order mark is skipped. Refusals are 400 invalid_body naming the column, with the row and its
// line (sky_radiance_rows.h for the values).
#pragma once

#include <string_view>
#include <vector>

#include "models/evaluation/measured_sky.h"

namespace clearsky::api {

std::vector<MeasuredCapture> parse_sky_radiance_csv(std::string_view text);

}  // namespace clearsky::api
