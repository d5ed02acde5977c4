// Fitted models (Preetham, Hosek) are formulas fitted to simulated skies; for a low sun their
// spectra turn negative near the horizon towards the sun (Preetham: the CIE daylight basis at
// chromaticities far from the daylight locus; Hosek: its constant term C). There the formula
// has no physical answer, so a sample is refused with outside_fit_domain, unless the user asks
// for the physical limit of no light (the option clamp_negative_fit), which internal integrals
// (the sky irradiance) always use.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>

#include "models/core/sample_status.h"

namespace clearsky {

// The option every fitted model shares.
inline constexpr const char* kClampNegativeFitOption = "clamp_negative_fit";

// Values below -1e-9 of the largest magnitude are the fit leaving its domain; smaller negative
// values are rounding and become 0. Returns ok, or outside_fit_domain when the fit turned
// negative and clamp is false (the values are then left as they are, for the caller to drop).
inline SampleStatus apply_fit_domain(std::span<double> spectrum, bool clamp) {
  double largest = 0.0;
  bool all_nonnegative = true;  // false for a NaN too, which the pass below handles
  for (double v : spectrum) {
    largest = std::max(largest, std::abs(v));
    all_nonnegative &= v >= 0.0;
  }
  // The usual case: one pass, nothing to clamp.
  if (all_nonnegative) return SampleStatus::ok;
  const double rounding = 1e-9 * largest;
  bool outside = false;
  for (double& v : spectrum) {
    if (v >= 0.0) continue;
    if (v < -rounding) outside = true;
    if (clamp || v >= -rounding) v = 0.0;
  }
  return outside && !clamp ? SampleStatus::outside_fit_domain : SampleStatus::ok;
}

}  // namespace clearsky
