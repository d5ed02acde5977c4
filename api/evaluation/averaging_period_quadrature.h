// The instants at which a model is evaluated to compare it with one measured broadband sample
// (docs/data-api.md "Averaged samples"), and their weights:
//  - an instantaneous sample (no averaging_s) is compared with the model at its instant;
//  - a sample that averages a period (averaging_s, api/datasets/irradiance_rows.h) is labelled at
//    the end of that period, the instant the logger wrote it (docs/measurement-formats.md
//    "Broadband irradiance"): it is compared with the model's mean over
//    [time - averaging_s, time];
//  - that mean is a Gauss-Legendre quadrature (models/core/quadrature.h): one node at the
//    period's middle for periods up to 60 s (the midpoint rule; its error, T^2/24 times the
//    curvature of the day's irradiance curve, is below 0.001 W/m2 for a minute), otherwise
//    3 nodes on each hour or part of an hour of the period (exact for polynomials of degree 5
//    on each hour: an hour of GHI is within 0.01 W/m2 where the midpoint misses by about 3).
// Cost: one model evaluation per instantaneous sample or sample of a minute or less, 3 per
// started hour of a longer period (an hourly series costs 3 times an instantaneous one); nodes
// with the sun below the horizon cost nothing (the model's irradiance there is zero).
// Thread-safe (pure functions).
#pragma once

#include <optional>
#include <vector>

namespace clearsky::api {

// Periods up to this length are averaged by their midpoint.
inline constexpr double kMidpointAveragingMaxS = 60.0;
// Longer periods get kNodesPerHour Gauss-Legendre nodes per started hour.
inline constexpr int kNodesPerHour = 3;

struct AveragingNode {
  double time_utc_s = 0;  // unix seconds
  double weight = 0;      // the weights of a sample's nodes sum to 1
};

// The nodes of a sample labelled `time_utc_s` averaging `averaging_s` seconds before it (none:
// the instant itself, weight 1).
std::vector<AveragingNode> averaging_nodes(double time_utc_s, std::optional<double> averaging_s);

// The instant that stands for the sample (the sun above the horizon there decides whether it
// is compared): its instant, or the middle of the period it averages.
double representative_time_utc_s(double time_utc_s, std::optional<double> averaging_s);

}  // namespace clearsky::api
