// Order statistics and Pareto fronts (error_summary.h).
#include "models/atlas/error_summary.h"

#include <algorithm>
#include <cmath>

namespace clearsky::atlas {

ErrorSummary summarise_errors(std::vector<double> errors) {
  ErrorSummary s;
  s.count = errors.size();
  if (errors.empty()) return s;
  std::sort(errors.begin(), errors.end());
  const auto rank = [&](double q) {
    // Nearest rank: the smallest value with at least q of the values at or below it.
    const auto k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(errors.size())));
    return errors[std::clamp<std::size_t>(k, 1, errors.size()) - 1];
  };
  s.median = rank(0.5);
  s.p95 = rank(0.95);
  s.max = errors.back();
  return s;
}

std::vector<std::string> pareto_front(std::vector<CostErrorPoint> points) {
  std::sort(points.begin(), points.end(), [](const CostErrorPoint& a, const CostErrorPoint& b) {
    return a.cost != b.cost ? a.cost < b.cost : a.error < b.error;
  });
  std::vector<std::string> front;
  double best_error = INFINITY;
  for (const CostErrorPoint& p : points) {
    if (p.error < best_error) {
      front.push_back(p.name);
      best_error = p.error;
    }
  }
  return front;
}

}  // namespace clearsky::atlas
