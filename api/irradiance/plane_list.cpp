// The planes of a series (plane_list.h).
#include "api/irradiance/plane_list.h"

#include "api/error/api_error.h"
#include "api/request/parameters.h"
#include "api/request/place_time.h"
#include "models/core/numeric.h"

namespace clearsky::api {

namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

double angle(std::string_view text, double min, double max, const char* what) {
  const std::string value(trimmed(text));
  double x = 0;
  try {
    x = number_value("planes", value);
  } catch (const ApiError&) {
    throw invalid_parameter("planes", std::string(what) + " must be a number, got '" + value +
                                          "' (planes=tilt:azimuth,...; e.g. 30:180,90:90)");
  }
  if (!(x >= min && x <= max))
    throw invalid_parameter("planes", std::string(what) + " must be in " +
                                          Interval{min, max}.text() + " degrees, got " + value);
  return x;
}

}  // namespace

PlaneOrientation SeriesPlane::orientation() const {
  return {degrees_to_radians(tilt_deg), degrees_to_radians(surface_azimuth_deg)};
}

std::vector<SeriesPlane> parse_planes(std::string_view text) {
  std::vector<SeriesPlane> planes;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = text.find(',', begin);
    const std::string_view item = text.substr(
        begin, comma == std::string_view::npos ? std::string_view::npos : comma - begin);
    const std::size_t colon = item.find(':');
    if (colon == std::string_view::npos || item.find(':', colon + 1) != std::string_view::npos)
      throw invalid_parameter("planes",
                              "each plane is tilt:azimuth in degrees (e.g. "
                              "planes=30:180,90:90), got '" +
                                  std::string(item) + "'");
    SeriesPlane plane;
    plane.tilt_deg = angle(item.substr(0, colon), 0.0, 180.0, "a tilt");
    plane.surface_azimuth_deg = angle(item.substr(colon + 1), -360.0, 360.0, "an azimuth");
    plane.suffix = "_";
    plane.suffix += trimmed(item.substr(0, colon));
    plane.suffix += '_';
    plane.suffix += trimmed(item.substr(colon + 1));
    for (const SeriesPlane& other : planes) {
      if (other.suffix == plane.suffix)
        throw invalid_parameter("planes", "plane " + std::string(item) + " is given twice");
    }
    planes.push_back(std::move(plane));
    if (planes.size() > kMaxPlanes)
      throw invalid_parameter("planes", "at most " + std::to_string(kMaxPlanes) + " planes");
    if (comma == std::string_view::npos) break;
    begin = comma + 1;
  }
  return planes;
}

}  // namespace clearsky::api
