// Finding the route of a request in the route table (route_table.h): the path is compared
// segment by segment with each pattern ({name} takes any non-empty segment, and is returned
// as a path parameter); a path that matches but not for this method gives the methods that
// would be answered (405 with Allow). HEAD is answered by the GET route.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "api/routes/route_table.h"

namespace clearsky::api {

struct RouteMatch {
  // The route for this method and path; null when none.
  const Route* route = nullptr;
  NameValues path_parameters;
  // The methods of the routes whose pattern matches the path, in table order; empty when no
  // pattern matches (404).
  std::vector<std::string_view> methods;
  // The pattern the path matched (the first in table order); empty when none.
  std::string_view pattern;

  bool path_known() const { return !methods.empty(); }
};

RouteMatch match_route(std::string_view method, std::string_view path);

// The Allow header of a known path: its methods, HEAD with GET, and OPTIONS.
std::string allow_header(const RouteMatch& match);

}  // namespace clearsky::api
