// The JSON form of the open sky-radiance format (docs/measurement-formats.md):
//   {"site": {"latitude", "longitude", "elevation_m"},            (optional: the file's site)
//    "samples": [{"time", "view_zenith", "view_azimuth", "wavelength_nm", "radiance",
//                 "latitude", "longitude", "elevation_m"}, ...]}  (the site when the file has
//                                                                  none, and only then)
// Numbers are JSON numbers, time a string. Refusals are 400 invalid_body naming the member
// (samples[11].radiance, site.latitude): the body, site and time through
// site_and_samples_json.h, the values through sky_radiance_rows.h.
#pragma once

#include <string_view>
#include <vector>

#include "models/evaluation/measured_sky.h"

namespace clearsky::api {

std::vector<MeasuredCapture> parse_sky_radiance_json(std::string_view text);

}  // namespace clearsky::api
