// Breakpoints along a ray at the tangent point and at altitude levels (see ray_quadrature.h).
#include "models/core/ray_quadrature.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "models/core/quadrature.h"
#include "models/core/ray_sphere.h"

namespace clearsky {

namespace {

// Level crossings of a part where the radius changes monotonically from the radius at
// d_from to the radius at d_to; the ladder starts at the part's lowest radius. Appends the
// distances strictly between the two ends in increasing order.
void append_level_crossings(double r, double mu, double d_from, double d_to, double step,
                            std::vector<double>& out) {
  const double r_from = radius_at_distance(r, mu, d_from);
  const double r_to = radius_at_distance(r, mu, d_to);
  const bool ascending = r_to >= r_from;
  const double low = std::min(r_from, r_to), high = std::max(r_from, r_to);
  const auto count = static_cast<long>(std::ceil((high - low) / step)) - 1;
  const std::size_t first = out.size();
  for (long k = 1; k <= count; ++k) {
    const double level = low + static_cast<double>(k) * step;
    const double root = safe_sqrt(ray_sphere_discriminant(r, mu, level));
    // Ascending parts cross each level at the far root, descending ones at the near root.
    const double d = ascending ? -r * mu + root : -r * mu - root;
    if (d > d_from && d < d_to) out.push_back(d);
  }
  if (!ascending) std::reverse(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
}

}  // namespace

std::vector<double> ray_breakpoints(double r_m, double mu, double d0_m, double d1_m,
                                    double altitude_step_m) {
  if (!(altitude_step_m > 0.0))
    throw std::invalid_argument("ray_breakpoints: altitude step must be > 0");
  std::vector<double> out;
  if (!(d1_m > d0_m)) return out;
  out.push_back(d0_m);
  const double tangent = -r_m * mu;  // distance of the lowest point of the whole line
  if (tangent > d0_m && tangent < d1_m) {
    append_level_crossings(r_m, mu, d0_m, tangent, altitude_step_m, out);
    out.push_back(tangent);
    append_level_crossings(r_m, mu, tangent, d1_m, altitude_step_m, out);
  } else {
    append_level_crossings(r_m, mu, d0_m, d1_m, altitude_step_m, out);
  }
  out.push_back(d1_m);
  return out;
}

std::vector<RayNode> ray_nodes(const std::vector<double>& breakpoints, int nodes_per_piece) {
  std::vector<RayNode> nodes;
  if (breakpoints.size() < 2) return nodes;
  const auto unit = gauss_legendre(nodes_per_piece, 0.0, 1.0);
  nodes.reserve((breakpoints.size() - 1) * unit.size());
  for (std::size_t p = 0; p + 1 < breakpoints.size(); ++p) {
    const double a = breakpoints[p], length = breakpoints[p + 1] - a;
    for (const auto& [t, w] : unit) {
      nodes.push_back({a + length * t, length * w, static_cast<int>(p)});
    }
  }
  return nodes;
}

}  // namespace clearsky
