// The instants and weights of an averaged sample (averaging_period_quadrature.h).
#include "api/evaluation/averaging_period_quadrature.h"

#include <cmath>

#include "models/core/quadrature.h"

namespace clearsky::api {

std::vector<AveragingNode> averaging_nodes(double time_utc_s, std::optional<double> averaging_s) {
  if (!averaging_s || !(*averaging_s > 0)) return {{time_utc_s, 1.0}};
  const double period_s = *averaging_s;
  const double start_s = time_utc_s - period_s;
  if (period_s <= kMidpointAveragingMaxS) return {{start_s + 0.5 * period_s, 1.0}};
  const int pieces = static_cast<int>(std::ceil(period_s / 3600.0));
  const double piece_s = period_s / pieces;
  std::vector<AveragingNode> nodes;
  nodes.reserve(static_cast<std::size_t>(pieces * kNodesPerHour));
  for (int p = 0; p < pieces; ++p) {
    // Weights on [0, piece/period]: the piece's share of the mean.
    for (const auto& [x, w] : gauss_legendre(kNodesPerHour, 0.0, 1.0))
      nodes.push_back({start_s + (p + x) * piece_s, w / pieces});
  }
  return nodes;
}

double representative_time_utc_s(double time_utc_s, std::optional<double> averaging_s) {
  if (!averaging_s || !(*averaging_s > 0)) return time_utc_s;
  return time_utc_s - 0.5 * *averaging_s;
}

}  // namespace clearsky::api
