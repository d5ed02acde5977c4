// Parsing of viewing directions.
#include "api/request/views.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "api/error/api_error.h"
#include "models/core/numeric.h"

namespace clearsky::api {

namespace {

void add_view(ViewList& list, double zenith_deg, double azimuth_deg) {
  list.zenith_deg.push_back(zenith_deg);
  list.azimuth_deg.push_back(azimuth_deg);
  list.views.push_back({degrees_to_radians(zenith_deg), degrees_to_radians(azimuth_deg)});
}

double view_angle(const nlohmann::json& value, const std::string& parameter, double min,
                  double max) {
  if (!value.is_number()) throw invalid_parameter(parameter, "angles must be numbers (degrees)");
  const double x = value.get<double>();
  if (!(std::isfinite(x) && x >= min && x <= max)) {
    throw invalid_parameter(parameter,
                            "zenith must be in [0, 180] and azimuth in [-360, 360] degrees");
  }
  return x;
}

}  // namespace

std::string ViewList::parameter(std::size_t i) const {
  return batch ? "views[" + std::to_string(i) + "]" : "view_zenith";
}

ViewList parse_single_view(Parameters& p) {
  ViewList list;
  add_view(list, p.required_number("view_zenith", 0.0, 180.0),
           p.required_number("view_azimuth", -360.0, 360.0));
  return list;
}

ViewList parse_view_batch(const nlohmann::json& views, const Limits& limits) {
  if (!views.is_array() || views.empty())
    throw invalid_parameter("views", "must be a non-empty array");
  if (views.size() > limits.max_views) {
    throw too_large("views", "at most " + std::to_string(limits.max_views) + " views per request");
  }
  ViewList list;
  list.batch = true;
  for (std::size_t i = 0; i < views.size(); ++i) {
    const std::string name = "views[" + std::to_string(i) + "]";
    const nlohmann::json& v = views[i];
    if (v.is_array() && v.size() == 2) {
      add_view(list, view_angle(v[0], name, 0.0, 180.0), view_angle(v[1], name, -360.0, 360.0));
    } else if (v.is_object()) {
      for (const auto& [key, value] : v.items()) {
        if (key != "view_zenith" && key != "view_azimuth")
          throw unknown_parameter(name + "." + key, "a view");
      }
      if (!v.contains("view_zenith") || !v.contains("view_azimuth")) {
        throw missing_parameter(name, "each view needs view_zenith and view_azimuth");
      }
      add_view(list, view_angle(v["view_zenith"], name, 0.0, 180.0),
               view_angle(v["view_azimuth"], name, -360.0, 360.0));
    } else {
      throw invalid_parameter(
          name, "a view is {\"view_zenith\": deg, \"view_azimuth\": deg} or [zenith, azimuth]");
    }
  }
  return list;
}

std::string status_parameter(SampleStatus status, const SunSpec& sun, const ViewList& views,
                             std::size_t i) {
  switch (status) {
    case SampleStatus::sun_below_horizon_unsupported:
      return sun.parameter;
    case SampleStatus::viewpoint_unsupported:
      return "altitude";
    case SampleStatus::wavelength_out_of_range:
      return "wavelengths";
    default:
      return views.parameter(i);
  }
}

}  // namespace clearsky::api
