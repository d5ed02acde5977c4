// The CSV form of the open broadband irradiance format (docs/measurement-formats.md "Broadband
// irradiance"; lines and fields as csv_lines.h): a header naming the columns time, latitude,
// longitude, elevation_m, at least one of ghi, dhi and dni, and optionally averaging_s, in any
// order, then one row per measured instant. An empty ghi, dhi or dni field is a value not
// measured at that instant. Refusals are 400 invalid_body naming the column, with the row and
// its line (irradiance_rows.h for the values).
#pragma once

#include <string_view>
#include <vector>

#include "storage/repositories/irradiance_sample_repository.h"

namespace clearsky::api {

std::vector<storage::IrradianceSample> parse_irradiance_csv(std::string_view text);

}  // namespace clearsky::api
