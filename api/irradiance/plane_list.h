// The planes of GET /v1/irradiance/series: planes=tilt:azimuth[,tilt:azimuth...], degrees
// (tilt from horizontal in [0, 180], azimuth of the normal clockwise from North in
// [-360, 360]), e.g. planes=30:180,90:180,90:90; at most kMaxPlanes. Each plane's column
// suffix is _<tilt>_<azimuth> as written in the request (poa_global_30_180). A malformed
// list, a value out of range or a plane given twice is a 400 naming planes.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "models/core/sky_model.h"

namespace clearsky::api {

struct SeriesPlane {
  double tilt_deg = 0;
  double surface_azimuth_deg = 180;
  std::string suffix;  // "_30_180"
  PlaneOrientation orientation() const;
};

inline constexpr std::size_t kMaxPlanes = 16;

std::vector<SeriesPlane> parse_planes(std::string_view text);

}  // namespace clearsky::api
