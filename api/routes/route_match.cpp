// Segment-by-segment matching of a path against the route table's patterns.
#include "api/routes/route_match.h"

#include <algorithm>

namespace clearsky::api {

namespace {

// The next segment of text after position at (which is at a '/'); advances at.
std::string_view next_segment(std::string_view text, std::size_t& at) {
  const std::size_t start = at + 1;
  const std::size_t end = std::min(text.find('/', start), text.size());
  at = end;
  return text.substr(start, end - start);
}

bool is_parameter(std::string_view segment) {
  return segment.size() > 2 && segment.front() == '{' && segment.back() == '}';
}

// Whether path matches pattern; fills parameters when given. Every request is matched against
// every row, so most rows are rejected by comparing the literal text before the first
// parameter (the whole pattern when it has none) before any segment is split.
bool matches(std::string_view pattern, std::string_view path, NameValues* parameters) {
  if (path.empty() || path.front() != '/') return false;
  const std::size_t literal = pattern.find('{');
  if (literal == std::string_view::npos) return path == pattern;
  if (path.substr(0, literal) != pattern.substr(0, literal)) return false;
  std::size_t p = 0;
  std::size_t q = 0;
  while (p < pattern.size() && q < path.size()) {
    const std::string_view expected = next_segment(pattern, p);
    const std::string_view actual = next_segment(path, q);
    if (is_parameter(expected)) {
      if (actual.empty()) return false;
      if (parameters != nullptr)
        parameters->emplace_back(expected.substr(1, expected.size() - 2), actual);
    } else if (expected != actual) {
      return false;
    }
  }
  return p >= pattern.size() && q >= path.size();
}

}  // namespace

RouteMatch match_route(std::string_view method, std::string_view path) {
  const std::string_view wanted = method == "HEAD" ? std::string_view("GET") : method;
  RouteMatch match;
  for (const Route& route : routes()) {
    if (!matches(route.pattern, path, nullptr)) continue;
    match.methods.push_back(route.method);
    if (match.pattern.empty()) match.pattern = route.pattern;
    if (match.route == nullptr && route.method == wanted) {
      match.route = &route;
      matches(route.pattern, path, &match.path_parameters);
    }
  }
  return match;
}

std::string allow_header(const RouteMatch& match) {
  std::string allow;
  const auto add = [&allow](std::string_view method) {
    if (!allow.empty()) allow += ", ";
    allow += method;
  };
  for (std::string_view method : match.methods) {
    add(method);
    if (method == "GET") add("HEAD");
  }
  add("OPTIONS");
  return allow;
}

}  // namespace clearsky::api
