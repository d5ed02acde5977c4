// Viewing directions of radiance and colour queries: one view from view_zenith/view_azimuth
// (degrees; GET), or a batch from the JSON body's "views" (POST): an array of
// {"view_zenith": deg, "view_azimuth": deg} objects or [zenith, azimuth] pairs.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "api/request/parameters.h"
#include "api/request/sky_request.h"
#include "models/core/geometry.h"

namespace clearsky::api {

struct ViewList {
  std::vector<ViewDirection> views;  // radians
  std::vector<double> zenith_deg, azimuth_deg;
  bool batch = false;
  // The parameter naming view i in errors: "view_zenith" or "views[i]".
  std::string parameter(std::size_t i) const;
};

ViewList parse_single_view(Parameters& p);
// 413 above limits.max_views; 400 naming "views[i]" for an invalid entry.
ViewList parse_view_batch(const nlohmann::json& views, const Limits& limits);

// The parameter a non-ok sample status is about (sun, altitude or the view).
std::string status_parameter(SampleStatus status, const SunSpec& sun, const ViewList& views,
                             std::size_t i);

}  // namespace clearsky::api
