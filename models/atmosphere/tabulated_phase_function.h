// A phase function known at tabulated scattering angles (a measured or retrieved one, such as
// the AERONET inversion's, models/aeronet/aeronet_phase_functions.h), as a function of the cosine
// of the scattering angle in 1/sr, normalised so that its integral over the sphere is 1 (the
// convention of phase_functions.h).
//
// Between the tabulated angles the logarithm of the value is linear in the angle (the forward
// peak falls by orders of magnitude within a few degrees, where a linear interpolation of the
// values would overestimate it). The normalisation is that of this interpolant, integrated
// numerically over 0..180 degrees, so that the function conserves energy whatever the scale of
// the input (AERONET's integrates to 4 pi; the table's own trapezoid sum differs by ~0.5%).
//
// Lookups read a table uniform in u = sin(theta / 2) = sqrt((1 - mu) / 2) (kLookupSize points,
// linear between them): no acos per lookup, 0.06 degree spacing in the forward peak, ~2 degrees
// near the backward direction, where phase functions are flat. Immutable; thread-safe.
#pragma once

#include <cmath>
#include <span>
#include <vector>

namespace clearsky {

class TabulatedPhaseFunction {
 public:
  static constexpr int kLookupSize = 2048;

  // angles_deg strictly increasing from 0 to 180, values > 0 (any common scale). Throws
  // InvalidInput("phase_function", ...) otherwise.
  TabulatedPhaseFunction(std::span<const double> angles_deg, std::span<const double> values);

  // The value (1/sr) at the cosine mu of the scattering angle (clamped to [-1, 1]).
  double operator()(double mu) const {
    if (std::isnan(mu)) return mu;  // as the closed forms of phase_functions.h answer
    const double u = (mu >= 1.0 ? 0.0 : mu <= -1.0 ? 1.0 : std::sqrt(0.5 * (1.0 - mu)));
    const double x = u * (kLookupSize - 1);
    int i = static_cast<int>(x);
    if (i >= kLookupSize - 1) i = kLookupSize - 2;
    const double f = x - i;
    return lookup_[i] + f * (lookup_[i + 1] - lookup_[i]);
  }

  // The interpolant at an angle (degrees), normalised: what the lookup table samples.
  double at_angle_deg(double angle_deg) const;
  // Mean cosine of the scattering angle (asymmetry parameter g) of the interpolant.
  double asymmetry() const { return asymmetry_; }

  const std::vector<double>& angles_deg() const { return angles_deg_; }
  // Tabulated values in 1/sr (the input divided by the normalisation).
  const std::vector<double>& values_per_sr() const { return values_; }

 private:
  std::vector<double> angles_deg_;
  std::vector<double> values_;  // normalised, 1/sr
  std::vector<double> lookup_;  // kLookupSize values, uniform in sin(theta / 2)
  double asymmetry_ = 0.0;
};

}  // namespace clearsky
