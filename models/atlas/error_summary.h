// Order statistics of relative errors and Pareto fronts for the atlas (atlas_report.h).
#pragma once

#include <string>
#include <vector>

#include "models/atlas/atlas_report.h"

namespace clearsky::atlas {

// Median, 95th percentile (nearest rank) and maximum; all zero for no errors.
ErrorSummary summarise_errors(std::vector<double> errors);

struct CostErrorPoint {
  std::string name;
  double cost = 0;
  double error = 0;
};

// The names of the points no other point beats on both cost and error (lower is better; a
// point equal on one and better on the other beats it), in increasing cost.
std::vector<std::string> pareto_front(std::vector<CostErrorPoint> points);

}  // namespace clearsky::atlas
