// Tabulated phase function: log-linear interpolation in angle, normalisation, lookup table.
#include "models/atmosphere/tabulated_phase_function.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "models/core/invalid_input.h"
#include "models/core/numeric.h"

namespace clearsky {

namespace {

// log-linear interpolation of (angles, values) at angle (degrees), clamped to the table's ends.
double interpolate(const std::vector<double>& angles, const std::vector<double>& values,
                   double angle) {
  if (angle <= angles.front()) return values.front();
  if (angle >= angles.back()) return values.back();
  const auto it = std::upper_bound(angles.begin(), angles.end(), angle);
  const std::size_t i = static_cast<std::size_t>(it - angles.begin()) - 1;
  const double f = (angle - angles[i]) / (angles[i + 1] - angles[i]);
  return std::exp((1.0 - f) * std::log(values[i]) + f * std::log(values[i + 1]));
}

}  // namespace

TabulatedPhaseFunction::TabulatedPhaseFunction(std::span<const double> angles_deg,
                                               std::span<const double> values)
    : angles_deg_(angles_deg.begin(), angles_deg.end()), values_(values.begin(), values.end()) {
  if (angles_deg_.size() < 2 || angles_deg_.size() != values_.size())
    throw InvalidInput("phase_function", "needs at least two angles, one value each");
  if (angles_deg_.front() != 0.0 || angles_deg_.back() != 180.0)
    throw InvalidInput("phase_function", "the angles must run from 0 to 180 degrees");
  for (std::size_t i = 0; i < angles_deg_.size(); ++i) {
    if (i > 0 && !(angles_deg_[i] > angles_deg_[i - 1]))
      throw InvalidInput("phase_function", "the angles must increase strictly");
    if (!(values_[i] > 0.0) || !std::isfinite(values_[i]))
      throw InvalidInput("phase_function", "value at " + std::to_string(angles_deg_[i]) +
                                               " degrees must be positive and finite");
  }
  // Integral over the sphere, 2 pi int P(theta) sin(theta) dtheta, and the mean cosine, by the
  // midpoint rule on 0.01-degree cells of the interpolant (the forward peak is resolved).
  constexpr int kCells = 18000;
  const double step = kPi / kCells;
  double integral = 0.0, first_moment = 0.0;
  for (int c = 0; c < kCells; ++c) {
    const double theta = (c + 0.5) * step;
    const double p = interpolate(angles_deg_, values_, radians_to_degrees(theta));
    integral += p * std::sin(theta) * step;
    first_moment += p * std::sin(theta) * std::cos(theta) * step;
  }
  integral *= 2.0 * kPi;
  first_moment *= 2.0 * kPi;
  asymmetry_ = first_moment / integral;
  for (double& v : values_) v /= integral;
  lookup_.resize(kLookupSize);
  for (int i = 0; i < kLookupSize; ++i) {
    const double u = static_cast<double>(i) / (kLookupSize - 1);
    lookup_[static_cast<std::size_t>(i)] = at_angle_deg(radians_to_degrees(2.0 * std::asin(u)));
  }
}

double TabulatedPhaseFunction::at_angle_deg(double angle_deg) const {
  return interpolate(angles_deg_, values_, angle_deg);
}

}  // namespace clearsky
