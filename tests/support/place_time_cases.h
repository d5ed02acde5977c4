// Values at and just beyond every limit of the place-and-time table (api/request/place_time.h),
// derived from the table itself, so that GET /v1/sun, the sky endpoints and `clearsky sun` are
// all checked against the same ranges.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "api/request/place_time.h"

namespace clearsky::testing {

struct PlaceTimeCase {
  std::string parameter;
  std::string value;
  bool accepted = false;  // within the range (the parser takes it)
};

inline std::string place_time_number_text(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

inline std::vector<PlaceTimeCase> place_time_cases() {
  using api::PlaceTimeKind;
  std::vector<PlaceTimeCase> cases;
  for (const api::PlaceTimeParameter& r : api::place_time_parameters()) {
    const std::string name(r.name);
    if (r.kind == PlaceTimeKind::boolean) {
      cases.push_back({name, "false", true});
      cases.push_back({name, "maybe", false});
      continue;
    }
    if (r.kind == PlaceTimeKind::time) {
      const int first = static_cast<int>(r.range.min);
      const int last = static_cast<int>(r.range.max);
      const auto year = [](int y) {
        std::ostringstream out;
        out.width(4);
        out.fill('0');
        out << y;
        return out.str();
      };
      cases.push_back({name, year(first) + "-01-01T00:00:00Z", true});
      cases.push_back({name, year(last) + "-12-31T23:59:59Z", true});
      cases.push_back({name, year(last + 1) + "-01-01T00:00:00Z", false});
      if (first > 0) cases.push_back({name, year(first - 1) + "-12-31T23:59:59Z", false});
      continue;
    }
    // A step well above the rounding of the limits, well below their width.
    const double step = (r.range.max - r.range.min) * 1e-6;
    cases.push_back(
        {name, place_time_number_text(r.range.min_open ? r.range.min + step : r.range.min), true});
    cases.push_back(
        {name, place_time_number_text(r.range.max_open ? r.range.max - step : r.range.max), true});
    cases.push_back(
        {name, place_time_number_text(r.range.min_open ? r.range.min : r.range.min - step), false});
    cases.push_back(
        {name, place_time_number_text(r.range.max_open ? r.range.max : r.range.max + step), false});
  }
  return cases;
}

}  // namespace clearsky::testing
