// The JSON form of the open broadband irradiance format (docs/measurement-formats.md
// "Broadband irradiance"):
//   {"site": {"latitude", "longitude", "elevation_m"},        (optional: the file's site)
//    "samples": [{"time", "ghi", "dhi", "dni", "averaging_s",
//                 "latitude", "longitude", "elevation_m"}, ...]}
// ghi, dhi, dni (W/m2) and averaging_s (s) are each optional, a null or an absent member being
// a value not measured; the site is in each sample when the file has none, and only then.
// Refusals are 400 invalid_body naming the member (samples[11].ghi, site.latitude): the body,
// site and time through site_and_samples_json.h, the values through irradiance_rows.h.
#pragma once

#include <string_view>
#include <vector>

#include "storage/repositories/irradiance_sample_repository.h"

namespace clearsky::api {

std::vector<storage::IrradianceSample> parse_irradiance_json(std::string_view text);

}  // namespace clearsky::api
